#include "lms100_driver/scan_stamper.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

// A 50 Hz sensor whose clock equals host time minus kEpoch: scan k starts at k · 20 ms and is
// transmitted kStartToTransmitUs later; the link adds kMinDelayUs to a telegram sent at once.
constexpr int64_t kEpoch = 1'700'000'000'000'000;
constexpr int64_t kPeriodUs = 20'000;
constexpr int64_t kStartToTransmitUs = 3'100;
constexpr int64_t kMinDelayUs = 150;

struct Telegram {
  uint32_t start_us;
  uint32_t transmit_us;
  int64_t true_start_utime;
};

Telegram telegram(int k) {
  const int64_t start = 1'000'000 + k * kPeriodUs;
  return {static_cast<uint32_t>(start), static_cast<uint32_t>(start + kStartToTransmitUs), kEpoch + start};
}
int64_t prompt_receive(int k) { return telegram(k).true_start_utime + kStartToTransmitUs + kMinDelayUs; }

struct Published {
  std::vector<LaserScan> scans;
  size_t release(ScanStamper& stamper, int64_t now) {
    return stamper.release(now, [this](const LaserScan& s) { scans.push_back(s); });
  }
};

LaserScan scan_with_counter(int k) {
  LaserScan s;
  s.scan_counter = static_cast<uint32_t>(k);
  s.ranges = {1.0F, 2.0F};
  return s;
}

/// Adds scans [first, last] as one read received at receive_utime, then releases.
size_t read(ScanStamper& stamper, Published& out, int first, int last, int64_t receive_utime) {
  for (int k = first; k <= last; ++k)
    stamper.add(scan_with_counter(k), telegram(k).start_us, telegram(k).transmit_us, receive_utime);
  return out.release(stamper, receive_utime + 50);
}

TEST(ScanStamper, BurstAfterConnectIsHeldThenStampedFromTheSettledEnvelope) {
  ScanStamper stamper;  // settle_reads 5
  Published out;
  // The first 5 scans in one read, when scan 4's telegram arrives (scan 0 waited 80 ms).
  EXPECT_EQ(read(stamper, out, 0, 4, prompt_receive(4)), 0u);
  EXPECT_EQ(stamper.held(), 5u);
  EXPECT_EQ(stamper.counts().scans_in_bursts, 4u);
  EXPECT_EQ(read(stamper, out, 5, 5, prompt_receive(5) + 7'000), 0u);  // late reads do not settle
  EXPECT_EQ(read(stamper, out, 6, 6, prompt_receive(6) + 3'000), 0u);
  EXPECT_EQ(read(stamper, out, 7, 7, prompt_receive(7)), 0u);
  EXPECT_EQ(read(stamper, out, 8, 8, prompt_receive(8)), 9u);  // fifth read: all nine go out in order
  ASSERT_EQ(out.scans.size(), 9u);
  for (int k = 0; k < 9; ++k) {
    const LaserScan& s = out.scans[static_cast<size_t>(k)];
    EXPECT_EQ(s.scan_counter, static_cast<uint32_t>(k));
    // Only the unobservable minimum delay remains in the stamp.
    EXPECT_EQ(s.utime - telegram(k).true_start_utime, kMinDelayUs) << "scan " << k;
    EXPECT_EQ(s.ranges.size(), 2u);
  }
  EXPECT_EQ(stamper.counts().held_scans, 8u);  // all but the one read just now
  // Scan 0 was read with the first burst and published four reads later.
  EXPECT_EQ(stamper.counts().held_scan_max_delay_us, prompt_receive(8) + 50 - prompt_receive(4));
  EXPECT_EQ(stamper.counts().held_scans_dropped, 0u);
  EXPECT_EQ(stamper.counts().utime_not_increasing, 0u);
}

TEST(ScanStamper, SettledStreamPublishesEachReadAtOnceAndAStallBurstStaysExact) {
  ScanStamper stamper;
  Published out;
  for (int k = 0; k < 10; ++k) read(stamper, out, k, k, prompt_receive(k));
  ASSERT_EQ(out.scans.size(), 10u);  // 0..4 held until the fifth read, then one per read
  // The host stalled 100 ms: scans 10..15 arrive together; the latest of them was 30 ms late.
  EXPECT_EQ(read(stamper, out, 10, 15, prompt_receive(15) + 30'000), 6u);
  ASSERT_EQ(out.scans.size(), 16u);
  for (size_t i = 0; i < out.scans.size(); ++i) {
    const int k = static_cast<int>(out.scans[i].scan_counter);
    EXPECT_EQ(out.scans[i].utime - telegram(k).true_start_utime, kMinDelayUs) << "scan " << k;
    if (i > 0) {
      EXPECT_GT(out.scans[i].utime, out.scans[i - 1].utime);
    }
  }
  EXPECT_EQ(stamper.counts().held_scans, 4u);
}

TEST(ScanStamper, DuplicateTelegramIsDroppedAsNotIncreasing) {
  ScanStamperConfig config;
  config.settle_reads = 1;
  ScanStamper stamper(config);
  Published out;
  read(stamper, out, 0, 0, prompt_receive(0));
  read(stamper, out, 1, 1, prompt_receive(1));
  read(stamper, out, 1, 1, prompt_receive(1) + 5'000);  // the same scan sent again
  EXPECT_EQ(out.scans.size(), 2u);
  EXPECT_EQ(stamper.counts().utime_not_increasing, 1u);
}

TEST(ScanStamper, ReconnectDropsHeldScansAndKeepsStampsIncreasing) {
  ScanStamper stamper;
  Published out;
  for (int k = 0; k < 8; ++k) read(stamper, out, k, k, prompt_receive(k));
  ASSERT_EQ(out.scans.size(), 8u);
  read(stamper, out, 8, 9, prompt_receive(9));
  stamper.reset();                                     // the link is lost
  EXPECT_EQ(stamper.counts().held_scans_dropped, 0u);  // settled: 8, 9 went out at once
  EXPECT_EQ(out.scans.size(), 10u);
  read(stamper, out, 60, 62, prompt_receive(62));  // after the reconnect: a burst of 3, then held
  stamper.reset();                                 // and the link is lost again
  EXPECT_EQ(stamper.counts().held_scans_dropped, 3u);
  for (int k = 100; k < 105; ++k) read(stamper, out, k, k, prompt_receive(k));
  ASSERT_EQ(out.scans.size(), 15u);
  EXPECT_EQ(out.scans[10].utime - telegram(100).true_start_utime, kMinDelayUs);
  for (size_t i = 1; i < out.scans.size(); ++i) EXPECT_GT(out.scans[i].utime, out.scans[i - 1].utime);
}

TEST(ScanStamper, OverflowWhileSettlingDropsTheOldestHeldScan) {
  ScanStamperConfig config;
  config.max_held_scans = 4;
  config.settle_reads = 2;
  ScanStamper stamper(config);
  Published out;
  read(stamper, out, 0, 5, prompt_receive(5));  // 6 in one read into 4 places
  EXPECT_EQ(stamper.counts().held_scans_dropped, 2u);
  read(stamper, out, 6, 6, prompt_receive(6));
  ASSERT_EQ(out.scans.size(), 4u);
  EXPECT_EQ(out.scans.front().scan_counter, 3u);  // 0..2 were dropped, 3..6 survive
  EXPECT_EQ(out.scans.back().scan_counter, 6u);
}

TEST(ScanStamper, SensorRebootRestartsTheFitAndHoldsAgain) {
  ScanStamper stamper;
  Published out;
  for (int k = 0; k < 10; ++k) read(stamper, out, k, k, prompt_receive(k));
  ASSERT_EQ(out.scans.size(), 10u);
  // The sensor rebooted: its clock starts again near 0 while host time goes on.
  const int64_t host = prompt_receive(10);
  for (int k = 0; k < 4; ++k) {
    stamper.add(scan_with_counter(200 + k), static_cast<uint32_t>(k * kPeriodUs),
                static_cast<uint32_t>(k * kPeriodUs + kStartToTransmitUs), host + k * kPeriodUs);
    out.release(stamper, host + k * kPeriodUs);
  }
  EXPECT_EQ(out.scans.size(), 10u);  // held until 5 reads after the restart
  EXPECT_EQ(stamper.clock().resets(), 1u);
  stamper.add(scan_with_counter(204), static_cast<uint32_t>(4 * kPeriodUs),
              static_cast<uint32_t>(4 * kPeriodUs + kStartToTransmitUs), host + 4 * kPeriodUs);
  out.release(stamper, host + 4 * kPeriodUs);
  ASSERT_EQ(out.scans.size(), 15u);
  EXPECT_EQ(out.scans[10].utime, host - kStartToTransmitUs);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
