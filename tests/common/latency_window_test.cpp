#include "common/latency_window.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(LatencyWindow, PercentilesOfKnownSamples) {
  LatencyWindow w(1000);
  for (int i = 1; i <= 100; ++i) w.add(i);
  EXPECT_NEAR(w.percentile(0.5), 50.5, 0.5);
  EXPECT_NEAR(w.percentile(0.99), 99.0, 1.0);
  EXPECT_EQ(w.percentile(0.0), 1.0);
  EXPECT_EQ(w.percentile(1.0), 100.0);
}

TEST(LatencyWindow, KeepsOnlyTheNewestSamples) {
  LatencyWindow w(10);
  for (int i = 0; i < 100; ++i) w.add(i);
  EXPECT_EQ(w.size(), 10u);
  EXPECT_EQ(w.percentile(0.0), 90.0);
}

TEST(LatencyWindow, EmptyGivesZero) { EXPECT_EQ(LatencyWindow().percentile(0.5), 0.0); }

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
