#pragma once
// Messages missing from a periodic stream, told from its stamps alone (ODOMETRY and
// LASER_POSE carry no sequence number): consecutive accepted stamps more than
// kGapPeriods nominal periods apart mean round(interval / period) - 1 messages were
// lost. The nominal period is learned, so the publisher's rate needs no config: an
// average of the intervals that are not gaps, restarted when an interval is less
// than half of it (the stream got faster, or the first interval was itself a gap).

#include <cstdint>

namespace refloc {

class StreamGapCounter {
 public:
  static constexpr double kGapPeriods = 2.5;

  /// The next accepted stamp of the stream [us]; how many messages went missing
  /// before it (0 for the first stamps, while the period is not yet known, and for a
  /// stamp not after the previous one: a re-anchored clock starts counting anew).
  int64_t on_stamp(int64_t utime);

  /// The learned nominal period [us]; 0 until known.
  double period_us() const { return period_us_; }

 private:
  bool have_previous_ = false;
  int64_t previous_utime_ = 0;
  double period_us_ = 0.0;
};

}  // namespace refloc
