#include "pose_fusion/stream_gap_counter.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

double StreamGapCounter::period_us() const {
  if (intervals_ < kMinIntervals) return 0.0;
  std::array<double, kWindow> sorted = intervals_us_;
  const auto end = sorted.begin() + static_cast<std::ptrdiff_t>(intervals_);
  const auto middle = sorted.begin() + static_cast<std::ptrdiff_t>(intervals_ / 2);
  std::nth_element(sorted.begin(), middle, end);
  return *middle;
}

int64_t StreamGapCounter::on_stamp(int64_t utime) {
  const bool had_previous = have_previous_;
  const int64_t previous = previous_utime_;
  have_previous_ = true;
  previous_utime_ = utime;
  if (!had_previous || utime <= previous) return 0;
  const double interval_us = static_cast<double>(utime) - static_cast<double>(previous);  // cannot overflow
  const double period = period_us();
  // Every interval joins the window, a gap too: one outage cannot move the median, and a
  // publisher that slowed down for good is learned instead of counted as gaps forever.
  intervals_us_[next_] = interval_us;
  next_ = (next_ + 1) % kWindow;
  intervals_ = std::min(intervals_ + 1, kWindow);
  if (period <= 0.0 || interval_us <= kGapPeriods * period) return 0;
  // Capped so a re-anchored clock's jump cannot overflow the count.
  return static_cast<int64_t>(std::llround(std::fmin(interval_us / period, 1e12))) - 1;
}

}  // namespace refloc
