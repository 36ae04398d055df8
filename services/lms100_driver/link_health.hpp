#pragma once
// What the driver says about its sensor link in HEARTBEAT: OK while the session streams and
// scans keep coming, DEGRADED while it (re)connects or scans pause, ERROR after
// error_after_s without a scan. The session thread reports scans and state changes; the
// heartbeat thread reads the verdict and the counters.

#include "lms100_driver/lms100_session.hpp"

#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

enum class LinkLevel { kOk, kDegraded, kError };

struct LinkVerdict {
  LinkLevel level = LinkLevel::kDegraded;
  std::string detail;
};

/// A streaming session is OK only while its last scan is younger than this [s].
inline constexpr double kStreamingFreshS = 1.0;

/// After a refused (implausible) scan the link stays DEGRADED this long [s], so a sensor that
/// sends every other scan wrong never looks OK.
inline constexpr double kRejectionHoldS = 1.0;
/// At most one log line about refused scans this often [s] (the first one at once).
inline constexpr double kRejectionLogPeriodS = 5.0;

/// The heartbeat verdict from the session state and how long no scan came (silent_s [s]).
LinkVerdict judge_link(SessionState state, const std::string& detail, double silent_s, double error_after_s);

/// The session's counters plus the driver's own, by heartbeat name, in a fixed order.
std::vector<std::pair<const char*, int64_t>> link_counters(const Lms100SessionCounters& session,
                                                           uint64_t publish_failures);

/// Thread-safe record of the link, written by the session thread, read by the heartbeat.
class LinkHealth {
 public:
  /// started_us: monotonic time [us] silence is counted from until the first scan.
  LinkHealth(double error_after_s, int64_t started_us)
      : error_after_s_(error_after_s), started_us_(started_us) {}

  void on_state(SessionState state, const std::string& detail);
  /// A scan was handed to the publisher at now_us [us monotonic], taking publish_us [us].
  void on_scan_published(int64_t now_us, int64_t publish_us, bool published);

  /// A scan was refused at now_us [us monotonic] for detail. Returns the line to log, or ""
  /// while the rate limit holds (the next line says how many were refused meanwhile).
  std::string on_scan_rejected(int64_t now_us, const std::string& detail);

  LinkVerdict verdict(int64_t now_us) const;
  uint64_t publish_failures() const { return publish_failures_.load(); }
  /// The last publish duration [us], 0 when none since the previous call.
  int64_t take_publish_time_us() { return last_publish_us_.exchange(0); }

 private:
  double error_after_s_;
  int64_t started_us_;
  mutable std::mutex mutex_;
  SessionState state_ = SessionState::kConnecting;
  std::string detail_ = "starting";
  int64_t last_rejection_us_ = 0;
  std::string rejection_detail_;
  int64_t last_rejection_log_us_ = 0;
  uint64_t rejections_since_log_ = 0;
  std::atomic<int64_t> last_scan_us_{0};
  std::atomic<int64_t> last_publish_us_{0};
  std::atomic<uint64_t> publish_failures_{0};
};

}  // namespace refloc
