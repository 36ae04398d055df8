// When refloc-status prints: --once a single time after --wait; live every second,
// and after a stall the next refresh is a second later, not a burst of missed ones.

#include "refresh_schedule.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(RefreshSchedule, OncePrintsASingleTimeAfterTheWait) {
  RefreshSchedule s(10.0, true, 3.0);
  EXPECT_FALSE(s.due(12.9));
  EXPECT_DOUBLE_EQ(s.seconds_until_due(12.5), 0.5);
  EXPECT_TRUE(s.due(13.0));
  EXPECT_TRUE(s.done());
  EXPECT_FALSE(s.due(20.0));
}

TEST(RefreshSchedule, LiveEverySecondOnTheStartsGrid) {
  RefreshSchedule s(10.0, false, 3.0);
  EXPECT_FALSE(s.due(10.5));
  EXPECT_TRUE(s.due(11.02));
  EXPECT_FALSE(s.due(11.5));
  EXPECT_DOUBLE_EQ(s.seconds_until_due(11.5), 0.5) << "next at 12.0, not 12.02";
  EXPECT_TRUE(s.due(12.0));
  EXPECT_FALSE(s.done());
}

TEST(RefreshSchedule, AStallDoesNotPrintInABurst) {
  RefreshSchedule s(0.0, false, 3.0);
  EXPECT_TRUE(s.due(5.3));  // four refreshes late
  EXPECT_FALSE(s.due(5.4));
  EXPECT_DOUBLE_EQ(s.seconds_until_due(5.3), 1.0);
  EXPECT_DOUBLE_EQ(s.seconds_until_due(7.0), 0.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
