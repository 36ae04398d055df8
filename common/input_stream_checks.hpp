#pragma once
// The per-stream checks a chain consumer (reflector_extractor, reflector_matcher,
// pose_solver) runs after it judged a message's content: its stamp (StampGuard) and,
// for streams numbered by the LMS100 scan counter, the messages missing before it.
// Both report as NodeEvents under the stream's counter names, so every service says
// "rejected_scan_stamp_ahead" or "gap_detections_messages" the same way.
// Header only: LCM-free, used by the three services' libraries.

#include "common/node_event.hpp"
#include "common/stamp_guard.hpp"

#include <fmt/format.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace refloc {

/// Why a message is not used; the reason word of its rejected_<input>_<reason> counter.
struct InputFault {
  const char* reason = nullptr;  ///< nullptr: usable; "nonfinite", "out_of_bounds", "covariance", ...
  std::string detail;            ///< for the log
  explicit operator bool() const { return reason != nullptr; }
};

/// What one message's scan counter says about the messages before it.
struct CounterStep {
  int64_t missing = 0;  ///< counter values skipped since the previous message
  bool reset = false;   ///< a jump time cannot explain (sensor restart, foreign counter): not a gap
};

/// Gaps in a stream numbered by the scan counter (uint16 on the wire in an int32; values
/// are taken modulo 65536, so the wrap 65535 -> 0 is one step). An advance is a gap only if
/// the time between the two messages could hold that many scans at kMinScanPeriod_us;
/// otherwise (a counter that jumps back after a sensor restart, or forward by thousands
/// within milliseconds) it is a reset and starts over. The stream's stride (the driver's
/// output_interval: every n-th scan sent) is the smallest advance seen; with stride 1,
/// the default, every skipped counter value is one missing message. The very first
/// advance teaches the stride, so a gap there is not counted.
class ScanCounterGaps {
 public:
  /// The fastest scan rate a message numbered this way can come at: 100 Hz (the LMS100
  /// scans at 25 or 50 Hz) [us].
  static constexpr int64_t kMinScanPeriod_us = 10'000;

  /// One message with its scan counter and stamp [us] (a stamp StampGuard accepted).
  CounterStep observe(int64_t scan_counter, int64_t utime) {
    const int64_t counter = scan_counter & 0xFFFF;
    CounterStep step;
    if (have_last_) {
      const int64_t advance = (counter - last_counter_) & 0xFFFF;
      int64_t elapsed_us = 0;
      if (__builtin_sub_overflow(utime, last_utime_, &elapsed_us)) elapsed_us = utime > 0 ? INT64_MAX : -1;
      const int64_t max_advance = elapsed_us > 0 ? elapsed_us / kMinScanPeriod_us + 1 : 1;
      if (advance == 0 || advance > max_advance) {
        step.reset = true;
      } else if (stride_ == 0 || advance < stride_) {
        stride_ = advance;
      } else {
        step.missing = advance / stride_ - 1;
      }
    }
    have_last_ = true;
    last_counter_ = counter;
    last_utime_ = utime;
    return step;
  }

 private:
  bool have_last_ = false;
  int64_t last_counter_ = 0;
  int64_t last_utime_ = 0;
  int64_t stride_ = 0;  ///< 0 until the first advance
};

/// Stamp limits for a stream another service of the chain publishes (LMS100_SCAN, REFLECTORS,
/// REFLECTOR_MATCHES, POSE): its stamps are scan or odometry times, and the time from
/// there to our handler includes the upstream service's processing, which varies by far
/// more than the default 0.1 s (a cold-started matcher's first global relocalization, a
/// busy host). The guard learns the stream's offset from the first message, so with the
/// default every prompt message after a slow first one would be "ahead" and lost until
/// the guard re-anchors (measured: 30 LASER_POSE of a 4 s replay). 1 s still rejects
/// every forged far-future stamp (+1 h, INT64_MAX).
inline StampGuardLimits chain_stream_stamp_limits() {
  StampGuardLimits limits;
  limits.max_ahead_us = 1'000'000;
  return limits;
}

/// One input stream's counter names, checks and health. <input> is the short stream name of the
/// heartbeat counters: rejected_<input>_<reason>, reanchored_<input>,
/// gap_<input>_messages, counter_reset_<input>.
class InputStreamChecks {
 public:
  explicit InputStreamChecks(std::string input, StampGuardLimits limits = {})
      : input_(std::move(input)), guard_(limits), gap_counter_(name("gap_" + input_ + "_messages")) {}
  // Events point into names_: a copy would point into the original's.
  InputStreamChecks(const InputStreamChecks&) = delete;
  InputStreamChecks& operator=(const InputStreamChecks&) = delete;
  InputStreamChecks(InputStreamChecks&&) = default;
  InputStreamChecks& operator=(InputStreamChecks&&) = default;

  const std::string& input() const { return input_; }
  /// "rejected_<input>_<reason>", valid as long as this object.
  const char* rejected_counter(const std::string& reason) {
    return name("rejected_" + input_ + "_" + reason);
  }
  const char* gap_counter() const { return gap_counter_; }

  /// The event for a message rejected for its content (reason: nonfinite, out_of_bounds,
  /// covariance, ...), with `why` for the log.
  NodeEvent rejected(const std::string& reason, const std::string& why, int64_t host_utime) {
    NodeEvent e{rejected_counter(reason), NodeEvent::Level::kWarn,
                fmt::format("{} rejected ({}): {}", input_, reason, why)};
    note_rejected(host_utime, e.log);
    return e;
  }

  /// A message of the stream passed every check at host_utime [us].
  void accepted(int64_t host_utime) {
    started(host_utime);
    last_accepted_host_utime_ = host_utime;
    rejected_since_accepted_ = false;
  }
  /// Messages come but none was usable for more than kStarvedAfter_us: the service cannot
  /// do its job on this input (DEGRADED), isolated rejections are only counted.
  bool starved(int64_t host_utime) const {
    return rejected_since_accepted_ && host_utime - last_accepted_host_utime_ > kStarvedAfter_us;
  }
  /// For state_detail while starved.
  std::string starved_detail(int64_t host_utime) const {
    return fmt::format("no usable {} for {:.1f} s; last: {}", input_,
                       static_cast<double>(host_utime - last_accepted_host_utime_) * 1e-6, last_rejection_);
  }
  static constexpr int64_t kStarvedAfter_us = 1'000'000;

  /// Judge the stamp [us] against the host clock [us]; false: rejected (event appended).
  bool stamp_accepted(int64_t stamp_utime, int64_t host_utime, std::vector<NodeEvent>& events) {
    const StampVerdict verdict = guard_.check(stamp_utime, host_utime);
    if (verdict == StampVerdict::kAccepted) return true;
    if (verdict == StampVerdict::kReanchored) {
      events.push_back(
          {name("reanchored_" + input_), NodeEvent::Level::kWarn,
           fmt::format("{}: the stream's clock stepped; re-anchored at stamp {}", input_, stamp_utime)});
      return true;
    }
    events.push_back({rejected_counter(std::string("stamp_") + to_string(verdict)), NodeEvent::Level::kWarn,
                      fmt::format("{} rejected: stamp {} is {} ({} us older than the stream's clock expects)",
                                  input_, stamp_utime, to_string(verdict), guard_.last_deviation_us())});
    note_rejected(host_utime, events.back().log);
    return false;
  }

  /// The scan counter of an accepted message: the messages missing before it (a log line
  /// appended when some are, or when the counter reset).
  int64_t missing_before(int64_t scan_counter, int64_t utime, std::vector<NodeEvent>& events) {
    const CounterStep step = gaps_.observe(scan_counter, utime);
    if (step.reset) {
      events.push_back({name("counter_reset_" + input_), NodeEvent::Level::kInfo,
                        fmt::format("{}: scan counter jumped to {} (sensor restart?): counting from there",
                                    input_, scan_counter)});
    } else if (step.missing > 0) {
      events.push_back({nullptr, NodeEvent::Level::kWarn,
                        fmt::format("{}: {} message(s) missing before scan counter {}", input_, step.missing,
                                    scan_counter)});
    }
    return step.missing;
  }

 private:
  void started(int64_t host_utime) {
    if (have_message_) return;
    have_message_ = true;
    last_accepted_host_utime_ = host_utime;  // starvation is timed from the first message
  }
  void note_rejected(int64_t host_utime, const std::string& why) {
    started(host_utime);
    rejected_since_accepted_ = true;
    last_rejection_ = why;
  }

  /// Counter names live as long as this object: NodeEvent carries a const char*.
  const char* name(const std::string& full) { return names_.insert(full).first->c_str(); }

  std::set<std::string> names_;  // first: gap_counter_ points into it
  std::string input_;
  StampGuard guard_;
  ScanCounterGaps gaps_;
  const char* gap_counter_;
  bool have_message_ = false;
  bool rejected_since_accepted_ = false;
  int64_t last_accepted_host_utime_ = 0;
  std::string last_rejection_;
};

}  // namespace refloc
