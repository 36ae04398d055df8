#include "mecanum_odometry/mecanum_odometry.hpp"

#include "mecanum_odometry/encoder_ticks.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

// Drives ideal wheels with a constant body twist and reports encoder counts,
// quantised and wrapped as a motor controller would.
class TickSource {
 public:
  TickSource(const RobotConfig& robot, int64_t start_ticks)
      : kinematics_(robot), ticks_per_rad_(robot.encoder_ticks_per_rev / (2.0 * M_PI)) {
    angle_.fill(start_ticks / ticks_per_rad_);
  }
  void advance(const BodyTwist& twist, double dt, const WheelArray& scale = {1, 1, 1, 1}) {
    const WheelArray w = kinematics_.inverse(twist);
    for (size_t i = 0; i < 4; ++i) angle_[i] += w[i] * scale[i] * dt;
  }
  std::array<int32_t, 4> ticks() const {
    std::array<int32_t, 4> t{};
    for (size_t i = 0; i < 4; ++i) {
      const auto count = static_cast<int64_t>(std::floor(angle_[i] * ticks_per_rad_));
      t[i] = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(count)));
    }
    return t;
  }

 private:
  MecanumKinematics kinematics_;
  double ticks_per_rad_;
  WheelArray angle_{};
};

struct DriveResult {
  MecanumOdometry odometry;
  double max_slip = 0.0;
};

DriveResult drive(const BodyTwist& twist, double duration, double rate_hz, int64_t start_ticks = 0,
                  const WheelArray& scale = {1, 1, 1, 1}) {
  const RobotConfig robot;
  DriveResult run{MecanumOdometry(robot, OdometryConfig{})};
  TickSource source(robot, start_ticks);
  const int steps = static_cast<int>(std::lround(duration * rate_hz));
  const auto period_us = static_cast<int64_t>(std::lround(1e6 / rate_hz));
  int64_t utime = 1'000'000;
  run.odometry.add_sample(utime, source.ticks());
  for (int i = 0; i < steps; ++i) {
    source.advance(twist, 1.0 / rate_hz, scale);
    utime += period_us;
    EXPECT_EQ(run.odometry.add_sample(utime, source.ticks()), EncoderSampleResult::kIntegrated);
    run.max_slip = std::max(run.max_slip, run.odometry.estimate().slip_indicator);
  }
  return run;
}

// One tick of one wheel moves the base by at most r * 2 pi / 16384 = 29 um.
constexpr double kQuantisation = 1e-4;

TEST(MecanumOdometry, StraightOneMetreForward) {
  const DriveResult run = drive({0.5, 0.0, 0.0}, 2.0, 100.0);
  const auto& e = run.odometry.estimate();
  EXPECT_NEAR(e.odom_T_robot.x, 1.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.y, 0.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.theta, 0.0, 1e-4);
  EXPECT_NEAR(e.twist.vx, 0.5, 0.01);
  EXPECT_NEAR(e.distance, 1.0, kQuantisation);
}

TEST(MecanumOdometry, SidewaysOneMetreLeft) {
  const DriveResult run = drive({0.0, 0.5, 0.0}, 2.0, 100.0);
  const auto& e = run.odometry.estimate();
  EXPECT_NEAR(e.odom_T_robot.x, 0.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.y, 1.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.theta, 0.0, 1e-4);
  EXPECT_NEAR(e.twist.vy, 0.5, 0.01);
}

TEST(MecanumOdometry, RotationInPlaceQuarterTurn) {
  const DriveResult run = drive({0.0, 0.0, M_PI / 4.0}, 2.0, 100.0);
  const auto& e = run.odometry.estimate();
  EXPECT_NEAR(e.odom_T_robot.x, 0.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.y, 0.0, kQuantisation);
  EXPECT_NEAR(e.odom_T_robot.theta, M_PI / 2.0, 2e-4);
  EXPECT_NEAR(e.twist.wz, M_PI / 4.0, 0.01);
}

TEST(MecanumOdometry, ArcMatchesTheAnalyticCircleEvenAtTenHertz) {
  // Radius 1 m centred at (0, 1), 6 s = 3 rad of arc; at 10 Hz a 0.05 rad step per
  // sample: Euler integration would be off by centimetres, the exact arc by the
  // quantisation only.
  for (double rate : {100.0, 10.0}) {
    const DriveResult run = drive({0.5, 0.0, 0.5}, 6.0, rate);
    const auto& e = run.odometry.estimate();
    EXPECT_NEAR(e.odom_T_robot.x, std::sin(3.0), 2e-4) << rate;
    EXPECT_NEAR(e.odom_T_robot.y, 1.0 - std::cos(3.0), 2e-4) << rate;
    EXPECT_NEAR(e.odom_T_robot.theta, 3.0, 2e-4) << rate;
    EXPECT_NEAR(e.distance, 3.0, 2e-4) << rate;
  }
}

TEST(MecanumOdometry, CountsWrappingAroundInt32AreSeamless) {
  const int64_t near_max = std::numeric_limits<int32_t>::max() - 50'000;
  const DriveResult run = drive({0.5, 0.0, 0.0}, 2.0, 100.0, near_max);  // 34000 ticks a metre
  EXPECT_NEAR(run.odometry.estimate().odom_T_robot.x, 1.0, kQuantisation);
  const DriveResult backwards =
      drive({-0.5, 0.0, 0.0}, 2.0, 100.0, std::numeric_limits<int32_t>::min() + 50'000);
  EXPECT_NEAR(backwards.odometry.estimate().odom_T_robot.x, -1.0, kQuantisation);
}

TEST(TickDelta, DifferenceAcrossTheWrapIsTheShortWay) {
  EXPECT_EQ(tick_delta(std::numeric_limits<int32_t>::min() + 5, std::numeric_limits<int32_t>::max() - 4), 10);
  EXPECT_EQ(tick_delta(std::numeric_limits<int32_t>::max() - 4, std::numeric_limits<int32_t>::min() + 5),
            -10);
  EXPECT_EQ(tick_delta(100, -100), 200);
}

TEST(MecanumOdometry, SlipIndicatorNearZeroWithoutSlip) {
  const DriveResult run = drive({0.4, 0.3, 0.5}, 3.0, 100.0);
  EXPECT_LT(run.max_slip, 0.004);  // one tick in 10 ms is 3 mm/s of wheel speed
}

TEST(MecanumOdometry, SlipIndicatorAboveThresholdWithOneWheelSlipping) {
  // Front-left spins 20 % faster than the ground under it: residual r/4 * 0.2 * w = 0.025 m/s.
  const DriveResult run = drive({0.5, 0.0, 0.0}, 1.0, 100.0, 0, {1.2, 1.0, 1.0, 1.0});
  EXPECT_GT(run.odometry.estimate().slip_indicator, 0.02);
  EXPECT_LT(run.odometry.estimate().slip_indicator, 0.03);
}

TEST(MecanumOdometry, CovarianceGrowsWithDistanceAndRotation) {
  const OdometryNoise noise;
  const DriveResult one = drive({0.5, 0.0, 0.0}, 2.0, 100.0);
  const DriveResult two = drive({0.5, 0.0, 0.0}, 4.0, 100.0);
  const auto& c1 = one.odometry.estimate().covariance;
  EXPECT_NEAR(c1(0, 0), noise.translation_variance_per_m * 1.0, 1e-6);
  EXPECT_NEAR(c1(2, 2), noise.heading_variance_per_m * 1.0, 1e-7);
  EXPECT_GT(c1(1, 1), c1(0, 0));  // heading uncertainty adds lateral uncertainty
  EXPECT_GT(two.odometry.estimate().covariance(1, 1), 2.0 * c1(1, 1));
  const DriveResult turn = drive({0.0, 0.0, 1.0}, 1.0, 100.0);
  EXPECT_NEAR(turn.odometry.estimate().covariance(2, 2), noise.heading_variance_per_rad * 1.0, 1e-6);
}

TEST(MecanumOdometry, OutOfOrderAndFirstSamplesAreNotIntegrated) {
  MecanumOdometry odometry(RobotConfig{}, OdometryConfig{});
  EXPECT_EQ(odometry.add_sample(1000, {0, 0, 0, 0}), EncoderSampleResult::kFirstSample);
  EXPECT_EQ(odometry.add_sample(1000, {10, 10, 10, 10}), EncoderSampleResult::kOutOfOrder);
  EXPECT_EQ(odometry.add_sample(5'000'000, {10, 10, 10, 10}), EncoderSampleResult::kGapRestart);
  EXPECT_EQ(odometry.add_sample(5'010'000, {100000, 0, 0, 0}), EncoderSampleResult::kImplausible);
  EXPECT_DOUBLE_EQ(odometry.estimate().odom_T_robot.x, 0.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
