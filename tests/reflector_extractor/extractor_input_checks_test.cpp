#include "reflector_extractor/extractor_input_checks.hpp"
#include "reflector_extractor/synthetic_scan.hpp"

#include "scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

LaserScan good_scan() {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(2.0, 0.3)};
  std::mt19937 rng(7);
  return render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
}

std::string reason_after(const std::function<void(LaserScan&)>& spoil) {
  LaserScan scan = good_scan();
  spoil(scan);
  const InputFault fault = check_scan(scan);
  return fault ? fault.reason : "usable";
}

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(ExtractorScanCheck, TheSyntheticAndLms100LikeScanIsUsable) { EXPECT_FALSE(check_scan(good_scan())); }

TEST(ExtractorScanCheck, ANanOrInfiniteRangeRejectsTheWholeScanAsNonfinite) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.ranges[100] = std::nanf(""); }), "nonfinite");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.ranges[0] = std::numeric_limits<float>::infinity(); }),
            "nonfinite");
}

TEST(ExtractorScanCheck, NonFiniteHeaderFieldsAreNonfinite) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.angle_increment = kNan; }), "nonfinite");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.start_angle = kInf; }), "nonfinite");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.time_increment = kNan; }), "nonfinite");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.scan_period = -kInf; }), "nonfinite");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.range_max = kNan; }), "nonfinite");
}

TEST(ExtractorScanCheck, BeamsSpanningMoreThanOneTurnOrAZeroIncrementAreOutOfBounds) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.angle_increment = 0.0; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.angle_increment = 0.1; }), "out_of_bounds");  // 541 x 0.1 rad
  EXPECT_EQ(reason_after([](LaserScan& s) { s.start_angle = 100.0; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) {
              s.ranges.clear();
              s.rssi.clear();
            }),
            "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) {
              s.ranges.resize(5000, 1.0f);
              s.rssi.resize(5000, 0);
            }),
            "out_of_bounds");
}

TEST(ExtractorScanCheck, BeamTimesLongerThanTheScanPeriodOrAnAbsurdPeriodAreOutOfBounds) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.time_increment = 1e-3; }), "out_of_bounds");  // 541 ms > 20 ms
  EXPECT_EQ(reason_after([](LaserScan& s) { s.time_increment = -1e-5; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.scan_period = 100.0; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.scan_period = 0.0; }), "out_of_bounds");
}

TEST(ExtractorScanCheck, NegativeOrKilometreRangesAndBadRangeLimitsAreOutOfBounds) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.ranges[3] = -1.0f; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.ranges[3] = 1000.0f; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.range_max = 1e300; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.range_min = s.range_max; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.range_min = -0.1; }), "out_of_bounds");
}

TEST(ExtractorScanCheck, RssiMustBeAbsentOrOnePerBeamWithEightOrSixteenBitsInRange) {
  EXPECT_EQ(reason_after([](LaserScan& s) { s.rssi.pop_back(); }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.rssi_bits = 12; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.rssi[10] = 1'000'000'000; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) { s.rssi[10] = -1; }), "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) {
              s.rssi_bits = 8;
              s.rssi[10] = 256;
            }),
            "out_of_bounds");
  EXPECT_EQ(reason_after([](LaserScan& s) {
              s.rssi.clear();
              s.rssi_bits = 0;
            }),
            "usable");
}

TEST(ExtractorOdometryCheck, ANanInfiniteOrAbsurdTwistIsNotUsable) {
  const auto reason = [](BodyTwist t) {
    OdometrySample s;
    s.utime = 1;
    s.twist = t;
    const InputFault f = check_odometry_twist(s);
    return std::string(f ? f.reason : "usable");
  };
  EXPECT_EQ(reason({0.8, -0.3, 1.0}), "usable");
  EXPECT_EQ(reason({kNan, 0.0, 0.0}), "nonfinite");
  EXPECT_EQ(reason({0.0, kInf, 0.0}), "nonfinite");
  EXPECT_EQ(reason({0.0, 0.0, kNan}), "nonfinite");
  EXPECT_EQ(reason({1e308, 0.0, 0.0}), "out_of_bounds");
  EXPECT_EQ(reason({0.0, -6.0, 0.0}), "out_of_bounds");
  EXPECT_EQ(reason({0.0, 0.0, 1e300}), "out_of_bounds");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
