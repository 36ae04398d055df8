#pragma once
// Lets through at most rate_hz messages a second, judged by the messages' own stamps (a replay
// at full speed is decimated as the live run was). A stamp that goes back more than a second
// (a log started again) restarts it.

#include <cstdint>

namespace refloc {

class RateDecimator {
 public:
  explicit RateDecimator(double rate_hz) : period_us_(1e6 / rate_hz) {}

  /// Whether the message stamped utime [us] is let through. Any stamp is safe: the arithmetic is
  /// in double (exact for every real stamp, < 2^53 us), so a hostile INT64_MIN cannot overflow.
  bool accept(int64_t utime) {
    const double t = static_cast<double>(utime);
    if (has_slot_ && t < slot_us_ - 1e6) has_slot_ = false;
    // A tenth of a period early still takes the next slot: 50 Hz in, 10 Hz out stays every
    // fifth scan when the stamps jitter.
    if (has_slot_ && t < slot_us_ + period_us_ - period_us_ / 10) return false;
    const bool far_behind = !has_slot_ || t - (slot_us_ + period_us_) > period_us_;
    slot_us_ = far_behind ? t : slot_us_ + period_us_;
    has_slot_ = true;
    return true;
  }

 private:
  double period_us_;
  bool has_slot_ = false;
  double slot_us_ = 0.0;  ///< the stamp slot of the last message let through [us]
};

}  // namespace refloc
