#pragma once
// Messages missing from a periodic stream, told from its stamps alone (ODOMETRY and
// LASER_POSE carry no sequence number): an interval between consecutive accepted stamps
// of more than kGapPeriods nominal periods means round(interval / period) - 1 messages were
// lost. The nominal period is learned, so the publisher's rate needs no config: the median
// of the last kWindow intervals. A median, not an average: one stray message 1 us after a
// real one (a duplicate, a hostile copy) must not make the period 1 us and every later
// interval a gap of thousands (a running mean did that: 28,721 "missing" ODOMETRY in a
// hostile-bus run of ~5,000). A publisher that really changes its rate is followed once
// the new intervals are the majority of the window.

#include <array>
#include <cstddef>
#include <cstdint>

namespace refloc {

class StreamGapCounter {
 public:
  static constexpr double kGapPeriods = 2.5;
  static constexpr size_t kWindow = 15;
  /// Intervals seen before gaps are counted: the period is not known from fewer.
  static constexpr size_t kMinIntervals = 5;

  /// The next accepted stamp of the stream [us]; how many messages went missing
  /// before it (0 while the period is not yet known, and for a stamp not after the
  /// previous one: a re-anchored clock starts counting anew).
  int64_t on_stamp(int64_t utime);

  /// The learned nominal period [us]; 0 until kMinIntervals intervals were seen.
  double period_us() const;

 private:
  bool have_previous_ = false;
  int64_t previous_utime_ = 0;
  std::array<double, kWindow> intervals_us_{};
  size_t intervals_ = 0;  ///< how many of intervals_us_ are filled
  size_t next_ = 0;       ///< where the next interval goes
};

}  // namespace refloc
