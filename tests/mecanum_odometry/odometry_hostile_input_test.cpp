// mecanum_odometry facing a hostile or broken encoder publisher: stamps an hour off,
// at the int64 limits, zero; absurd count jumps. Nothing non-finite is published, every
// refusal is counted, later good samples are integrated, and a stream that arrives but
// publishes nothing is not OK.

#include "mecanum_odometry/odometry_node.hpp"

#include "common/input_sanity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;  // a plausible wall-clock stamp [us]
constexpr int64_t kPeriod = 10'000;             // encoders at 100 Hz
constexpr int64_t kHour = 3'600'000'000;

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

/// All four wheels forward 20 ticks per sample (0.058 m/s with the default robot).
EncoderReading sample_at(int k) {
  const int32_t t = 20 * k;
  return {kT0 + k * kPeriod, {t, t, t, t}};
}
int64_t mono(int k) { return 1'000'000 + k * kPeriod; }
int64_t host(int k) { return kT0 + k * kPeriod + 500; }

bool finite(const OdometryEstimate& e) {
  return all_finite({e.odom_T_robot.x, e.odom_T_robot.y, e.odom_T_robot.theta, e.twist.vx, e.twist.vy,
                     e.twist.wz, e.distance, e.slip_indicator}) &&
         e.covariance.allFinite();
}

TEST(OdometryHostileInput, OneSampleStampedFarOffIsRefusedAndTheStreamKeepsFlowing) {
  const std::vector<std::pair<int64_t, std::string>> stamps = {
      {kT0 + 50 * kPeriod + kHour, "rejected_wheel_encoders_stamp_ahead"},
      {std::numeric_limits<int64_t>::max(), "rejected_wheel_encoders_stamp_ahead"},
      {0, "rejected_wheel_encoders_stamp_behind"},
      {kT0 - kHour, "rejected_wheel_encoders_stamp_behind"},
      {std::numeric_limits<int64_t>::min(), "rejected_wheel_encoders_stamp_behind"},
      {-kHour, "rejected_wheel_encoders_stamp_behind"},
  };
  for (const auto& [stamp, counter] : stamps) {
    OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
    for (int k = 0; k < 50; ++k) ASSERT_NE(node.on_encoders(sample_at(k), mono(k), host(k)), nullptr);
    EncoderReading bad = sample_at(50);
    bad.utime = stamp;
    EXPECT_EQ(node.on_encoders(bad, mono(50), host(50)), nullptr) << stamp;
    EXPECT_EQ(count(node.events(), counter), 1) << stamp;
    EXPECT_EQ(node.events()[0].level, NodeEvent::Level::kWarn);
    const OdometryEstimate* last = nullptr;
    for (int k = 50; k < 150; ++k) {
      last = node.on_encoders(sample_at(k), mono(k), host(k));
      ASSERT_NE(last, nullptr) << "sample " << k << " after stamp " << stamp;
      EXPECT_TRUE(finite(*last));
    }
    EXPECT_EQ(last->utime, kT0 + 149 * kPeriod);
    EXPECT_NEAR(last->twist.vx, 0.058, 0.002);
    EXPECT_TRUE(node.health(mono(149)).ok);
  }
}

TEST(OdometryHostileInput, AbsurdCountJumpsAreSkippedAndNeverIntegrated) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  for (int k = 0; k < 50; ++k) node.on_encoders(sample_at(k), mono(k), host(k));
  const double x_before = node.on_encoders(sample_at(50), mono(50), host(50))->odom_T_robot.x;
  for (const int32_t jump :
       {std::numeric_limits<int32_t>::max(), std::numeric_limits<int32_t>::min(), 1 << 30}) {
    EncoderReading bad = sample_at(51);
    bad.ticks = {jump, jump, jump / 2, 0};
    const OdometryEstimate* e = node.on_encoders(bad, mono(51), host(51));
    ASSERT_NE(e, nullptr);
    EXPECT_TRUE(finite(*e));
    EXPECT_EQ(count(node.events(), "implausible_samples"), 1) << jump;
    EXPECT_NEAR(e->odom_T_robot.x, x_before, 1e-9) << jump;
    // Back to the genuine counts: refused once more (the jump back), then integrated.
    node.on_encoders(sample_at(52), mono(52), host(52));
    node.on_encoders(sample_at(53), mono(53), host(53));
    EXPECT_EQ(count(node.events(), "implausible_samples"), 0) << jump;
    // Re-run the same three steps for the next jump.
    node = OdometryNode(RobotConfig{}, OdometryServiceConfig{});
    for (int k = 0; k <= 50; ++k) node.on_encoders(sample_at(k), mono(k), host(k));
  }
}

TEST(OdometryHostileInput, APersistentEncoderClockStepIsBelievedAndIntegrationRestartsFromIt) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  for (int k = 0; k < 50; ++k) node.on_encoders(sample_at(k), mono(k), host(k));
  // The encoder clock jumps an hour ahead and stays there.
  int refused = 0, reanchored = 0;
  const OdometryEstimate* last = nullptr;
  for (int k = 50; k < 150; ++k) {
    EncoderReading r = sample_at(k);
    r.utime += kHour;
    last = node.on_encoders(r, mono(k), host(k));
    refused += last == nullptr;
    reanchored += count(node.events(), "reanchored_wheel_encoders");
  }
  EXPECT_EQ(reanchored, 1);
  EXPECT_GE(refused, 10);
  EXPECT_LT(refused, 60);
  ASSERT_NE(last, nullptr);
  EXPECT_TRUE(finite(*last));
  EXPECT_NEAR(last->twist.vx, 0.058, 0.002);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
