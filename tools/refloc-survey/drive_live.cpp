#include "drive_live.hpp"

#include "common/json_config.hpp"
#include "common/lcm_url.hpp"

#include <fmt/format.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

namespace refloc {
namespace {

volatile std::sig_atomic_t g_stop_requested = 0;

void on_stop_signal(int /*signal*/) { g_stop_requested = 1; }

/// Writes each message of the two channels to the log as it arrives, in bus order.
class DriveRecorder {
 public:
  DriveRecorder(const DriveLiveOptions& o, DriveLiveCounts& counts)
      : o_(o), counts_(counts), log_(o.record_path, "w") {
    if (!log_.good()) throw ConfigError(o.record_path + ": cannot write an LCM log there");
  }
  /// A write failed: nothing more is written; the caller stops and reports it (no exception
  /// through LCM's C dispatch).
  bool write_failed() const { return write_failed_; }
  void on_message(const lcm::ReceiveBuffer* buffer, const std::string& channel) {
    if (write_failed_) return;
    lcm::LogEvent event;
    event.eventnum = next_event_++;
    event.timestamp = buffer->recv_utime;
    event.channel = channel;
    event.datalen = static_cast<int32_t>(buffer->data_size);
    event.data = buffer->data;
    if (log_.writeEvent(&event) != 0) {
      write_failed_ = true;
      return;
    }
    ++(channel == o_.scan_channel       ? counts_.scans
       : channel == o_.odometry_channel ? counts_.odometry
                                        : counts_.truth);
  }

 private:
  const DriveLiveOptions& o_;
  DriveLiveCounts& counts_;
  lcm::LogFile log_;
  int64_t next_event_ = 0;
  bool write_failed_ = false;
};

}  // namespace

const char* stop_reason(DriveLiveCounts::Stop stop) {
  switch (stop) {
    case DriveLiveCounts::Stop::kInterrupted:
      return "stopped by the user";
    case DriveLiveCounts::Stop::kDuration:
      return "--duration-s reached";
    case DriveLiveCounts::Stop::kTimeout:
      return "no scan within --timeout-s";
  }
  return "?";
}

DriveLiveCounts record_drive_live(const DriveLiveOptions& o) {
  const LcmUrl url = resolve_lcm_url(o.lcm_url, std::getenv("LCM_DEFAULT_URL"));
  lcm::LCM bus(url.url);
  if (!bus.good())
    throw std::runtime_error("cannot open LCM at '" + url.url + "' (is there a multicast route?)");
  DriveLiveCounts counts;
  DriveRecorder recorder(o, counts);
  bus.subscribe(o.scan_channel, &DriveRecorder::on_message, &recorder);
  bus.subscribe(o.odometry_channel, &DriveRecorder::on_message, &recorder);
  if (!o.truth_channel.empty()) bus.subscribe(o.truth_channel, &DriveRecorder::on_message, &recorder);
  g_stop_requested = 0;
  std::signal(SIGINT, on_stop_signal);
  std::signal(SIGTERM, on_stop_signal);
  fmt::print("recording {} and {} from {} to {}: drive the robot through the hall, Ctrl-C to end{}\n",
             o.scan_channel, o.odometry_channel, url.url, o.record_path,
             o.duration_s > 0.0 ? fmt::format(" (or {:.0f} s)", o.duration_s) : "");
  std::fflush(stdout);
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last_scan = start, last_progress = start;
  int64_t scans_seen = 0;
  const auto seconds = [](Clock::duration d) { return std::chrono::duration<double>(d).count(); };
  while (true) {
    bus.handleTimeout(100);
    const auto now = Clock::now();
    if (counts.scans != scans_seen) scans_seen = counts.scans, last_scan = now;
    if (g_stop_requested || recorder.write_failed()) {
      counts.stop = DriveLiveCounts::Stop::kInterrupted;
      break;
    }
    if (o.duration_s > 0.0 && seconds(now - start) >= o.duration_s) {
      counts.stop = DriveLiveCounts::Stop::kDuration;
      break;
    }
    if (seconds(now - last_scan) > o.timeout_s) {
      counts.stop = DriveLiveCounts::Stop::kTimeout;
      break;
    }
    if (seconds(now - last_progress) >= 2.0) {
      last_progress = now;
      fmt::print("  {:.0f} s: {} scans, {} odometry\n", seconds(now - start), counts.scans, counts.odometry);
      std::fflush(stdout);
    }
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (recorder.write_failed()) throw ConfigError(o.record_path + ": write failed (disk full?)");
  fmt::print("recorded {} scans and {} odometry messages in {:.1f} s ({})\n", counts.scans, counts.odometry,
             seconds(Clock::now() - start), stop_reason(counts.stop));
  return counts;
}

}  // namespace refloc
