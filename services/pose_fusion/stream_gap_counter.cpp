#include "pose_fusion/stream_gap_counter.hpp"

#include <cmath>

namespace refloc {

int64_t StreamGapCounter::on_stamp(int64_t utime) {
  const bool had_previous = have_previous_;
  const int64_t previous = previous_utime_;
  have_previous_ = true;
  previous_utime_ = utime;
  if (!had_previous || utime <= previous) return 0;
  const double interval_us = static_cast<double>(utime) - static_cast<double>(previous);  // cannot overflow
  if (period_us_ <= 0.0 || interval_us < 0.5 * period_us_) {
    period_us_ = interval_us;
    return 0;
  }
  if (interval_us > kGapPeriods * period_us_) {
    // Capped so a re-anchored clock's jump cannot overflow the count.
    return static_cast<int64_t>(std::llround(std::fmin(interval_us / period_us_, 1e12))) - 1;
  }
  period_us_ += 0.05 * (interval_us - period_us_);
  return 0;
}

}  // namespace refloc
