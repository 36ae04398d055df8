#pragma once
// At most one log line per key per interval. A service that rejects a hostile or broken
// input at 50 Hz must say so, but one line a second (with how many it did not write) says
// it as well as fifty, and keeps the journal and the CPU for the robot.
// StateChangeLogLimiter does the same for a service's own state changes: a solver flapping
// between OK and DEGRADED at the scan rate wrote 563 lines in 70 s.

#include <cstdint>
#include <map>
#include <optional>
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

/// The log lines of a service's state changes (heartbeat_t states by name). A change is logged
/// at once; changes within interval of the last line are counted instead, and once interval has
/// passed one summary line says how many there were, to which states, and the state now. A change
/// into ERROR is never held back behind other changes (only behind an ERROR line of the same
/// interval), nor is STOPPING.
class StateChangeLogLimiter {
 public:
  struct Line {
    bool error = false;  ///< write at error level (the state is ERROR)
    std::string text;    ///< "state DEGRADED (was OK): last fix DEGRADED"
  };

  explicit StateChangeLogLimiter(int64_t interval_us = 10'000'000) : interval_us_(interval_us) {}

  /// The service's state or detail changed at now_us (monotonic clock): the line to write now, if any.
  std::optional<Line> on_change(int8_t state, const std::string& detail, int64_t now_us);
  /// Called periodically (the runtime: every second): the summary line when changes were held
  /// back and interval has passed since the last line.
  std::optional<Line> on_tick(int64_t now_us);

  int64_t held_back() const { return held_back_; }

 private:
  Line change_line(int8_t state, const std::string& detail) const;
  /// " (N changes in the last S s not logged one by one: aX OK, bX DEGRADED)" and forgets them; "" when none.
  std::string take_held_back(int64_t now_us);

  int64_t interval_us_;
  bool logged_ = false;  ///< a line was written (last_line_us is meaningful)
  int64_t last_line_us_ = 0;
  bool error_logged_ = false;
  int64_t last_error_line_us_ = 0;
  int8_t logged_state_ = 0;                 ///< the state the last line named
  int8_t state_ = 0;                        ///< the state now
  std::string detail_;                      ///< its detail now
  int64_t held_back_ = 0;                   ///< changes since the last line that were not logged
  std::map<int8_t, int64_t> held_back_to_;  ///< of those, how many into each state
};

}  // namespace refloc
