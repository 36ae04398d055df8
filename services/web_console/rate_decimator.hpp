#pragma once
// Lets through at most rate_hz messages a second, judged by the messages' own stamps (a replay
// at full speed is decimated as the live run was). A stamp that goes back more than a second
// (a log started again) restarts it.

#include <cstdint>

namespace refloc {

class RateDecimator {
 public:
  explicit RateDecimator(double rate_hz) : period_us_(static_cast<int64_t>(1e6 / rate_hz)) {}

  /// Whether the message stamped utime [us] is let through.
  bool accept(int64_t utime) {
    if (slot_us_ >= 0 && utime < slot_us_ - 1'000'000) slot_us_ = -1;
    // A tenth of a period early still takes the next slot: 50 Hz in, 10 Hz out stays every
    // fifth scan when the stamps jitter.
    if (slot_us_ >= 0 && utime < slot_us_ + period_us_ - period_us_ / 10) return false;
    const bool far_behind = slot_us_ < 0 || utime - (slot_us_ + period_us_) > period_us_;
    slot_us_ = far_behind ? utime : slot_us_ + period_us_;
    return true;
  }

 private:
  int64_t period_us_;
  int64_t slot_us_ = -1;  ///< the stamp slot of the last message let through [us]
};

}  // namespace refloc
