#pragma once
// Reading an LCM log file event by event with LCM's own reader (lcm::LogFile).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace refloc {

/// One logged event; data is valid only during the callback.
struct LogEventView {
  int64_t eventnum = 0;
  int64_t log_utime = 0;  ///< when lcm-logger received it [us since epoch]
  const std::string* channel = nullptr;
  const uint8_t* data = nullptr;
  size_t size = 0;
};

/// Call on_event for every event in order; returns the number of events.
/// Throws ConfigError when the file cannot be opened as an LCM log.
size_t for_each_log_event(const std::string& path, const std::function<void(const LogEventView&)>& on_event);

}  // namespace refloc
