// Angle math (common/angles.hpp): the one wrap convention and degree conversion.

#include "common/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(WrapAngle, MapsIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(wrap_angle(M_PI), M_PI);
  EXPECT_DOUBLE_EQ(wrap_angle(-M_PI), M_PI);
  EXPECT_NEAR(wrap_angle(3 * M_PI / 2), -M_PI / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-7.0), -7.0 + 2 * M_PI, 1e-12);
  for (double a = -20.0; a < 20.0; a += 0.01) {
    const double w = wrap_angle(a);
    EXPECT_GT(w, -M_PI);
    EXPECT_LE(w, M_PI);
    EXPECT_NEAR(std::sin(w), std::sin(a), 1e-9);
    EXPECT_NEAR(std::cos(w), std::cos(a), 1e-9);
  }
}

TEST(WrapAngle, LeavesAnAngleInsideTheIntervalBitForBit) {
  // Wrapping a wrapped heading must not move it, or re-wrapping would drift.
  for (double a = -3.14; a < 3.14; a += 0.001) EXPECT_EQ(wrap_angle(a), a);
}

TEST(CircularMean, AveragesAcrossTheWrap) {
  // The arithmetic mean of 179 deg and -179 deg is 0; the circular mean is 180 deg.
  EXPECT_NEAR(std::abs(circular_mean({deg_to_rad(179), deg_to_rad(-179)})), M_PI, 1e-12);
  EXPECT_NEAR(circular_mean({deg_to_rad(10), deg_to_rad(20), deg_to_rad(30)}), deg_to_rad(20), 1e-12);
  EXPECT_NEAR(circular_mean({0.0, M_PI / 2}, {3.0, 1.0}), std::atan2(1.0, 3.0), 1e-12);
  EXPECT_EQ(circular_mean(std::vector<double>{}), 0.0);
}

TEST(DegreeConversion, RoundTripsAndHitsKnownValues) {
  EXPECT_DOUBLE_EQ(deg_to_rad(180.0), M_PI);
  EXPECT_DOUBLE_EQ(deg_to_rad(90.0), M_PI / 2);
  EXPECT_DOUBLE_EQ(deg_to_rad(-135.0), -0.75 * M_PI);
  EXPECT_DOUBLE_EQ(rad_to_deg(M_PI / 4), 45.0);
  EXPECT_DOUBLE_EQ(kDegToRad, M_PI / 180.0);
  // Config readers turn a default back to degrees and the result to radians again.
  for (double rad : {0.5 * M_PI / 180.0, 10.0 * M_PI / 180.0, 1.2345}) {
    EXPECT_DOUBLE_EQ(deg_to_rad(rad_to_deg(rad)), rad);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
