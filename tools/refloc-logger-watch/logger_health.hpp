#pragma once
// Is lcm-logger recording? lcm-logger publishes no heartbeat and, on a full disk
// or a bad path, exits and is restarted without anyone noticing. This unit turns
// what refloc-logger-watch observes once a second (the logger process, the size
// of the file it writes, the traffic on the bus, the free space) into a heartbeat
// state and reason. No LCM in here.

#include <cstdint>
#include <string>
#include <utility>

namespace refloc {

struct LoggerWatchConfig {
  /// Below this much free space on the log's file system the logger is about to stop [bytes].
  int64_t min_free_bytes = 100LL * 1024 * 1024;
  /// The bus carried messages but the log did not change for this long: not recording [s].
  /// lcm-logger flushes every 100 ms, so a few seconds is a wide margin.
  double stall_s = 5.0;
  /// Shown in reasons, e.g. "logs/" or "/opt/refloc/logs/".
  std::string log_dir_label = "logs/";
};

/// One look at the logger (refloc-logger-watch takes one every second).
struct LoggerObservation {
  double now_s = 0.0;           ///< monotonic [s]
  bool logger_running = false;  ///< the lcm-logger child is alive
  std::string last_exit;        ///< how it last ended, e.g. "exit 1: <its last stderr line>"
  int64_t log_file_bytes = -1;  ///< size of the file being written; -1 when it does not exist
  uint64_t log_file_inode = 0;  ///< changes when lcm-logger rotates to a new file
  int64_t bus_messages = 0;     ///< messages heard on the bus so far (any channel)
  int64_t free_bytes = -1;      ///< free space for an unprivileged writer in the log dir; -1 unknown
};

struct LoggerVerdict {
  int8_t state = 0;  ///< heartbeat_t::STATE_* (1 OK, 3 ERROR)
  std::string detail;
};

class LoggerHealth {
 public:
  explicit LoggerHealth(LoggerWatchConfig config) : config_(std::move(config)) {}

  /// Worst first: disk full, logger not running, log not growing while the bus is busy.
  LoggerVerdict evaluate(const LoggerObservation& seen);

 private:
  LoggerWatchConfig config_;
  bool have_reference_ = false;
  double unlogged_since_s_ = -1.0;  ///< first look with bus traffic newer than the file; < 0: none
  int64_t reference_bytes_ = -1;
  uint64_t reference_inode_ = 0;
  int64_t reference_bus_messages_ = 0;  ///< bus count when the log file last changed
};

}  // namespace refloc

namespace refloc {

/// Size and inode of the log file into seen (-1 / 0 when it does not exist) and the free
/// space of its directory's file system for an unprivileged writer (-1 when unknown).
void probe_log_file(const std::string& log_file, LoggerObservation& seen);

}  // namespace refloc
