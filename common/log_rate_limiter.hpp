#pragma once
// At most one log line per key per interval. A service that rejects a hostile or broken
// input at 50 Hz must say so, but one line a second (with how many it did not write) says
// it as well as fifty, and keeps the journal and the CPU for the robot.

#include <cstdint>
#include <map>
#include <string>

namespace refloc {

class LogRateLimiter {
 public:
  explicit LogRateLimiter(int64_t interval_us = 1'000'000) : interval_us_(interval_us) {}

  /// True when a line for key may be written at now_us. suppressed is set to the number of
  /// lines for key held back since the last one written (0 when none).
  bool allow(const std::string& key, int64_t now_us, int64_t& suppressed);

 private:
  struct KeyState {
    int64_t last_written_us = 0;
    int64_t suppressed = 0;
    bool written = false;
  };
  int64_t interval_us_;
  std::map<std::string, KeyState> keys_;
};

}  // namespace refloc
