#pragma once
// refloc-survey drive --live: records the drive's scans and odometry from the bus into an LCM
// log (LCM's own writer) until Ctrl-C, --duration-s or --timeout-s without a scan; the survey
// then runs on that log exactly as on one recorded by lcm-logger, so a live survey and the same
// drive surveyed later from its log give the same map, and the log stays for the next survey.

#include <cstdint>
#include <string>

namespace refloc {

struct DriveLiveOptions {
  std::string lcm_url;  ///< empty: LCM_DEFAULT_URL, else LCM's default
  std::string scan_channel = "LMS100_SCAN";
  std::string odometry_channel = "ODOMETRY";
  std::string truth_channel;  ///< simulation: also recorded (GROUND_TRUTH); empty: not
  std::string record_path;    ///< the log written
  double duration_s = 0.0;    ///< 0: until Ctrl-C (SIGINT / SIGTERM)
  double timeout_s = 10.0;    ///< stop when no scan came for this long [s]
};

struct DriveLiveCounts {
  int64_t scans = 0;
  int64_t odometry = 0;
  int64_t truth = 0;
  enum class Stop { kInterrupted, kDuration, kTimeout } stop = Stop::kInterrupted;
};

/// Subscribes to both channels, prints a progress line every 2 s and writes every message of
/// theirs to o.record_path. Throws ConfigError when the log cannot be written, runtime_error when
/// the bus cannot be opened.
DriveLiveCounts record_drive_live(const DriveLiveOptions& o);

const char* stop_reason(DriveLiveCounts::Stop stop);

}  // namespace refloc
