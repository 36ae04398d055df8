#include "common/input_stream_checks.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;
constexpr int64_t kPeriod = 20'000;  // 50 Hz [us]

TEST(ScanCounterGaps, ConsecutiveCountersMissNothing) {
  ScanCounterGaps gaps;
  for (int i = 0; i < 100; ++i) {
    const CounterStep step = gaps.observe(1000 + i, kT0 + i * kPeriod);
    EXPECT_EQ(step.missing, 0);
    EXPECT_FALSE(step.reset);
  }
}

TEST(ScanCounterGaps, SkippedCountersAreTheMissingMessages) {
  ScanCounterGaps gaps;
  gaps.observe(10, kT0);
  gaps.observe(11, kT0 + kPeriod);
  const CounterStep step = gaps.observe(15, kT0 + 5 * kPeriod);
  EXPECT_EQ(step.missing, 3);
  EXPECT_FALSE(step.reset);
}

TEST(ScanCounterGaps, TheSixteenBitWrapIsOneStepNotAGap) {
  ScanCounterGaps gaps;
  gaps.observe(65534, kT0);
  EXPECT_EQ(gaps.observe(65535, kT0 + kPeriod).missing, 0);
  const CounterStep wrapped = gaps.observe(0, kT0 + 2 * kPeriod);
  EXPECT_EQ(wrapped.missing, 0);
  EXPECT_FALSE(wrapped.reset);
  EXPECT_EQ(gaps.observe(3, kT0 + 5 * kPeriod).missing, 2);
}

TEST(ScanCounterGaps, ASensorRestartIsAResetNotAGapOfSixtyFiveThousand) {
  ScanCounterGaps gaps;
  gaps.observe(5000, kT0);
  gaps.observe(5001, kT0 + kPeriod);
  const CounterStep restart = gaps.observe(0, kT0 + 3 * kPeriod);  // counter jumps back
  EXPECT_TRUE(restart.reset);
  EXPECT_EQ(restart.missing, 0);
  EXPECT_EQ(gaps.observe(1, kT0 + 4 * kPeriod).missing, 0);  // counting resumes from there
}

TEST(ScanCounterGaps, AForwardJumpTheElapsedTimeCannotHoldIsAReset) {
  ScanCounterGaps gaps;
  gaps.observe(100, kT0);
  gaps.observe(101, kT0 + kPeriod);
  const CounterStep jump = gaps.observe(20'000, kT0 + 2 * kPeriod);  // a restart 40 ms later at 20000
  EXPECT_TRUE(jump.reset);
  EXPECT_EQ(jump.missing, 0);
}

TEST(ScanCounterGaps, ALongOutageCountsEveryScanItCouldHold) {
  ScanCounterGaps gaps;
  gaps.observe(100, kT0);
  gaps.observe(101, kT0 + kPeriod);
  EXPECT_EQ(gaps.observe(601, kT0 + 501 * kPeriod).missing, 499);  // 10 s without scans at 50 Hz
}

TEST(ScanCounterGaps, AStreamOfEverySecondScanLearnsItsStride) {
  ScanCounterGaps gaps;  // the driver's output_interval 2: counters 0, 2, 4, ...
  for (int i = 0; i < 10; ++i) EXPECT_EQ(gaps.observe(2 * i, kT0 + 2 * i * kPeriod).missing, 0);
  EXPECT_EQ(gaps.observe(24, kT0 + 24 * kPeriod).missing, 2);  // 20 and 22 missing
}

TEST(ScanCounterGaps, ForgedCountersBeyondSixteenBitsAreTakenModulo65536) {
  ScanCounterGaps gaps;
  gaps.observe(65536 + 7, kT0);
  EXPECT_EQ(gaps.observe(8, kT0 + kPeriod).missing, 0);
  EXPECT_TRUE(gaps.observe(-1, kT0 + 2 * kPeriod).reset);  // 65535: far behind 8
}

TEST(InputStreamChecks, AFutureStampIsRejectedUnderTheStreamsCounterAndTheStreamGoesOn) {
  InputStreamChecks checks("scan");
  std::vector<NodeEvent> events;
  ASSERT_TRUE(checks.stamp_accepted(kT0, kT0 + 5'000, events));
  ASSERT_FALSE(checks.stamp_accepted(kT0 + 3'600'000'000, kT0 + 25'000, events));
  ASSERT_EQ(events.size(), 1u);
  EXPECT_STREQ(events[0].counter, "rejected_scan_stamp_ahead");
  EXPECT_EQ(events[0].level, NodeEvent::Level::kWarn);
  EXPECT_TRUE(checks.stamp_accepted(kT0 + 2 * kPeriod, kT0 + 2 * kPeriod + 5'000, events));
  EXPECT_EQ(events.size(), 1u);
}

TEST(InputStreamChecks, ContentRejectionsNameTheInputAndTheReason) {
  InputStreamChecks checks("detections");
  const NodeEvent e = checks.rejected("nonfinite", "x = nan", kT0);
  EXPECT_STREQ(e.counter, "rejected_detections_nonfinite");
  EXPECT_NE(e.log.find("x = nan"), std::string::npos);
  EXPECT_STREQ(checks.gap_counter(), "gap_detections_messages");
}

TEST(InputStreamChecks, OnlyRejectionsForOverASecondStarveTheInput) {
  InputStreamChecks checks("matches");
  checks.accepted(kT0);
  checks.rejected("nonfinite", "one", kT0 + 500'000);
  EXPECT_FALSE(checks.starved(kT0 + 900'000));  // an isolated rejection is only counted
  checks.rejected("nonfinite", "two", kT0 + 1'200'000);
  EXPECT_TRUE(checks.starved(kT0 + 1'200'000));
  EXPECT_NE(checks.starved_detail(kT0 + 1'200'000).find("no usable matches for 1.2 s"), std::string::npos);
  checks.accepted(kT0 + 1'300'000);
  EXPECT_FALSE(checks.starved(kT0 + 3'000'000));  // silence is not starvation: nothing was rejected
}

TEST(InputStreamChecks, AGapIsLoggedAndACounterResetCounted) {
  InputStreamChecks checks("scan");
  std::vector<NodeEvent> events;
  EXPECT_EQ(checks.missing_before(1, kT0, events), 0);
  EXPECT_EQ(checks.missing_before(2, kT0 + kPeriod, events), 0);  // the first step teaches the stride
  EXPECT_EQ(checks.missing_before(5, kT0 + 4 * kPeriod, events), 2);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].counter, nullptr);  // gap_scan_messages is bumped by the count, not by one
  EXPECT_EQ(checks.missing_before(0, kT0 + 5 * kPeriod, events), 0);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_STREQ(events[1].counter, "counter_reset_scan");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
