#include "robot_sim/mecanum_plant.hpp"

#include "mecanum_odometry/mecanum_odometry.hpp"
#include "robot_sim/encoder_model.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kStart = 1'000'000;

// Keep commanding twist every 20 ms (as the navigator does) for duration [s].
void hold(MecanumPlant& plant, const BodyTwist& twist, double duration) {
  const int64_t end = plant.utime() + static_cast<int64_t>(std::llround(duration * 1e6));
  while (plant.utime() < end) {
    plant.command(twist, plant.utime());
    plant.advance_to(std::min(end, plant.utime() + 20'000));
  }
}

TEST(MecanumPlant, ForwardCommandRampsUpUnderTheAccelerationLimit) {
  const RobotConfig robot;
  MecanumPlant plant(robot, PlantConfig{}, Pose2{}, kStart);
  hold(plant, {0.5, 0.0, 0.0}, 2.0);
  const double ramp_s = 0.5 / robot.wheel_radius / robot.max_wheel_accel;  // 0.329 s
  EXPECT_NEAR(plant.map_T_robot().x, 0.5 * (2.0 - ramp_s / 2.0), 1e-3);
  EXPECT_NEAR(plant.map_T_robot().y, 0.0, 1e-9);
  EXPECT_NEAR(plant.body_twist().vx, 0.5, 1e-9);
}

TEST(MecanumPlant, WheelSpeedLimitScalesTheCommandKeepingItsDirection) {
  const RobotConfig robot;
  MecanumPlant plant(robot, PlantConfig{}, Pose2{}, kStart);
  hold(plant, {3.0, 3.0, 0.0}, 2.0);
  // Diagonal: two wheels carry (vx + vy) / r; limited to 20 rad/s -> 0.76 m/s per axis.
  const double limited = robot.max_wheel_speed * robot.wheel_radius / 2.0;
  EXPECT_NEAR(plant.body_twist().vx, limited, 1e-9);
  EXPECT_NEAR(plant.body_twist().vy, limited, 1e-9);
  for (double w : plant.wheel_speeds()) EXPECT_LE(std::abs(w), robot.max_wheel_speed + 1e-9);
}

TEST(MecanumPlant, StaleCommandStopsEveryWheelAfterTheTimeout) {
  const RobotConfig robot;
  MecanumPlant plant(robot, PlantConfig{}, Pose2{}, kStart);
  hold(plant, {0.5, 0.0, 0.5}, 1.0);
  const int64_t last_command = plant.utime() - 20'000;
  plant.advance_to(last_command + 190'000);  // still within 200 ms: keeps going
  EXPECT_NEAR(plant.body_twist().vx, 0.5, 1e-9);
  // 200 ms timeout + at most 11.2 rad/s / 20 rad/s^2 = 0.56 s of ramp-down.
  plant.advance_to(last_command + 200'000 + 600'000);
  for (double w : plant.wheel_speeds()) EXPECT_EQ(w, 0.0);
  const Pose2 stopped = plant.map_T_robot();
  plant.advance_to(plant.utime() + 1'000'000);
  EXPECT_TRUE(approx_equal(plant.map_T_robot(), stopped, 1e-12, 1e-12));
}

TEST(MecanumPlant, OdometryFromItsEncodersFollowsTheTruePoseWithoutSlip) {
  const RobotConfig robot;
  MecanumPlant plant(robot, PlantConfig{}, Pose2{}, kStart);
  const EncoderModel encoders(robot.encoder_ticks_per_rev, std::numeric_limits<int32_t>::max() - 100'000);
  MecanumOdometry odometry(robot, OdometryConfig{});
  double max_slip = 0.0;
  for (int i = 0; i <= 500; ++i) {  // 5 s at 100 Hz, wrapping int32 on the way
    const BodyTwist cmd{0.6 * std::cos(0.01 * i), 0.3, 0.4};
    plant.command(cmd, plant.utime());
    plant.advance_to(kStart + i * 10'000);
    odometry.add_sample(plant.utime(), encoders.counts(plant.wheel_angles()));
    max_slip = std::max(max_slip, odometry.estimate().slip_indicator);
  }
  EXPECT_TRUE(approx_equal(odometry.estimate().odom_T_robot, plant.map_T_robot(), 1e-3, 1e-3));
  EXPECT_LT(max_slip, 0.005);
}

struct SlipRun {
  double slip_indicator;
  double odometry_excess_x;  ///< odometry x minus true x [m]
};

SlipRun drive_one_metre_with(const SlipConfig& slip) {
  const RobotConfig robot;
  PlantConfig config;
  config.slip = slip;
  MecanumPlant plant(robot, config, Pose2{}, kStart);
  const EncoderModel encoders(robot.encoder_ticks_per_rev);
  MecanumOdometry odometry(robot, OdometryConfig{});
  for (int i = 0; i <= 200; ++i) {
    plant.command({0.5, 0.0, 0.0}, plant.utime());
    plant.advance_to(kStart + i * 10'000);
    odometry.add_sample(plant.utime(), encoders.counts(plant.wheel_angles()));
  }
  return {odometry.estimate().slip_indicator, odometry.estimate().odom_T_robot.x - plant.map_T_robot().x};
}

TEST(MecanumPlant, SpinningWheelShowsAsSlipAndOdometryDrift) {
  SlipConfig slip;
  slip.spin_excess = {0.2, 0.0, 0.0, 0.0};
  const SlipRun run = drive_one_metre_with(slip);
  // r/4 * 0.2 * w = 0.2 * 0.5 / 4 = 0.025 m/s; odometry over-reads by 0.025 / 0.5 = 5 %.
  EXPECT_NEAR(run.slip_indicator, 0.025, 0.003);
  EXPECT_NEAR(run.odometry_excess_x, 0.05 * 0.918, 0.005);
}

TEST(MecanumPlant, ScaleErrorDriftsOdometryButIsInvisibleToTheSlipIndicator) {
  SlipConfig slip;
  slip.scale_error = {-0.2, 0.0, 0.0, 0.0};
  const SlipRun run = drive_one_metre_with(slip);
  EXPECT_LT(run.slip_indicator, 0.004);
  EXPECT_NEAR(run.odometry_excess_x, 0.05 * 0.918, 0.005);
}

TEST(EncoderModel, CountsAreWholeTicksAndWrapAsInt32) {
  const EncoderModel encoders(16384, std::numeric_limits<int32_t>::max());
  const auto counts = encoders.counts({0.0, 2.0 * M_PI / 16384 * 1.5, -1e-9, 2.0 * M_PI});
  EXPECT_EQ(counts[0], std::numeric_limits<int32_t>::max());
  EXPECT_EQ(counts[1], std::numeric_limits<int32_t>::min());  // +1 tick wraps
  EXPECT_EQ(counts[2], std::numeric_limits<int32_t>::max() - 1);
  EXPECT_EQ(counts[3], std::numeric_limits<int32_t>::min() + 16383);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
