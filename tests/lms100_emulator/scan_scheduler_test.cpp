#include "lms100_emulator/scan_scheduler.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(ScanScheduler, ScansFollowAFixedGridOnePeriodApartWithCountersPlusOne) {
  ScanScheduler scheduler(200000, 20000, 65534);
  scheduler.start(0);
  ScanSlot slot;
  EXPECT_FALSE(scheduler.pop_due_scan(199999, 16000, slot));
  EXPECT_FALSE(scheduler.pop_due_scan(200000, 16000, slot));  // grid starts at readiness
  EXPECT_TRUE(scheduler.pop_due_scan(216000, 16000, slot));
  EXPECT_EQ(slot.start_us, 200000u);
  EXPECT_EQ(slot.complete_us, 216000u);
  EXPECT_EQ(slot.scan_counter, 65534);
  EXPECT_FALSE(scheduler.pop_due_scan(235999, 16000, slot));
  // A late caller still gets each scan at its own grid time (no drift), the counter wraps.
  EXPECT_TRUE(scheduler.pop_due_scan(260000, 16000, slot));
  EXPECT_EQ(slot.start_us, 220000u);
  EXPECT_EQ(slot.scan_counter, 65535);
  EXPECT_TRUE(scheduler.pop_due_scan(260000, 16000, slot));
  EXPECT_EQ(slot.start_us, 240000u);
  EXPECT_EQ(slot.scan_counter, 0);
  EXPECT_FALSE(scheduler.pop_due_scan(260000, 16000, slot));
  EXPECT_EQ(scheduler.next_event_us(260000, 16000), 276000u);
}

TEST(ScanScheduler, FarBehindSkipsScansButCountsThem) {
  ScanScheduler scheduler(0, 20000, 0);
  scheduler.start(0);
  ScanSlot slot;
  ASSERT_FALSE(scheduler.pop_due_scan(0, 1000, slot));
  ASSERT_TRUE(scheduler.pop_due_scan(1000, 1000, slot));
  EXPECT_EQ(slot.scan_counter, 0);
  ASSERT_TRUE(scheduler.pop_due_scan(1000000, 1000, slot));  // 50 periods late
  EXPECT_EQ(slot.start_us, 980000u);
  EXPECT_EQ(slot.scan_counter, 49);
}

TEST(ScanScheduler, StatusGoesThreeFourFiveSevenOverTheSpinUp) {
  ScanScheduler scheduler(1000000, 20000, 0);
  EXPECT_EQ(scheduler.status_code(0), 3);
  scheduler.start(1000000);
  EXPECT_EQ(scheduler.status_code(1000000), 3);
  EXPECT_EQ(scheduler.status_code(1299999), 3);
  EXPECT_EQ(scheduler.status_code(1300000), 4);
  EXPECT_EQ(scheduler.status_code(1800000), 5);
  EXPECT_EQ(scheduler.status_code(2000000), 7);
  scheduler.stop();
  EXPECT_EQ(scheduler.status_code(2000000), 3);
  ScanSlot slot;
  EXPECT_FALSE(scheduler.pop_due_scan(3000000, 1000, slot));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
