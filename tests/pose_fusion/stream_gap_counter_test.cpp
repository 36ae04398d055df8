// Gaps in a stream without sequence numbers, from its stamps: a lost run of messages is
// counted once, stray or duplicate stamps do not change the learned period.

#include "pose_fusion/stream_gap_counter.hpp"

#include <gtest/gtest.h>

#include <cstdint>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kPeriodUs = 10'000;  // 100 Hz ODOMETRY

int64_t feed_regular(StreamGapCounter& gaps, int64_t& t, int n) {
  int64_t missing = 0;
  for (int i = 0; i < n; ++i) missing += gaps.on_stamp(t += kPeriodUs);
  return missing;
}

TEST(StreamGapCounter, ARunOfLostMessagesIsCountedOnce) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  EXPECT_EQ(feed_regular(gaps, t, 20), 0);
  EXPECT_DOUBLE_EQ(gaps.period_us(), kPeriodUs);
  t += 7 * kPeriodUs;  // 7 messages lost
  EXPECT_EQ(gaps.on_stamp(t += kPeriodUs), 7);
  EXPECT_EQ(feed_regular(gaps, t, 20), 0);
}

TEST(StreamGapCounter, NothingIsCountedBeforeThePeriodIsKnown) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  EXPECT_EQ(gaps.on_stamp(t), 0);
  EXPECT_EQ(gaps.on_stamp(t += 50 * kPeriodUs), 0);
  EXPECT_EQ(gaps.period_us(), 0.0);
}

TEST(StreamGapCounter, AStrayStampJustAfterARealOneDoesNotMakeEveryIntervalAGap) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  feed_regular(gaps, t, 20);
  int64_t missing = 0;
  for (int k = 0; k < 5; ++k) {  // a hostile copy with utime + 1 us after every 4th message
    missing += gaps.on_stamp(t + 1);
    t += 1;
    missing += feed_regular(gaps, t, 4);
  }
  EXPECT_EQ(missing, 0);
  EXPECT_NEAR(gaps.period_us(), kPeriodUs, 2.0);
}

TEST(StreamGapCounter, JitterWithinTheGapLimitIsNoGap) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  int64_t missing = 0;
  uint32_t state = 12345;  // intervals spread over 5..15 ms, a stream at 100 Hz with heavy jitter
  for (int i = 0; i < 1000; ++i) {
    state = state * 1664525U + 1013904223U;
    missing += gaps.on_stamp(t += 5'000 + static_cast<int64_t>(state >> 8) % 10'001);
  }
  EXPECT_EQ(missing, 0);
}

TEST(StreamGapCounter, APublisherThatSlowsDownForGoodIsLearned) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  feed_regular(gaps, t, 20);
  int64_t late = 0;
  for (int i = 0; i < 30; ++i) {
    const int64_t missing = gaps.on_stamp(t += 10 * kPeriodUs);
    if (i >= 10) late += missing;
  }
  EXPECT_EQ(late, 0) << "still counting gaps after the new rate is the window's majority";
  EXPECT_DOUBLE_EQ(gaps.period_us(), 10.0 * kPeriodUs);
}

TEST(StreamGapCounter, AClockGoingBackStartsOver) {
  StreamGapCounter gaps;
  int64_t t = 1'000'000'000;
  feed_regular(gaps, t, 20);
  EXPECT_EQ(gaps.on_stamp(t - 5'000'000), 0);
  t -= 5'000'000;
  EXPECT_EQ(feed_regular(gaps, t, 5), 0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
