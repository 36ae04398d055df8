#include "odometry_calibration.hpp"
#include "synthetic_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

OdometryCalibrationResult solve_drive(const test::SyntheticDriveSpec& spec) {
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  OdometryCalibrationOptions o;
  o.odometry_noise = spec.nominal.odometry_noise;
  return calibrate_odometry(odometry_windows(drive, spec.nominal, WindowOptions{}), o);
}

TEST(OdometryCalibration, RecoversRadiusAndGeometryScalesWithinATenthOfAPercent) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  spec.nominal.robot_T_laser = spec.truth.robot_T_laser;  // the mount already calibrated
  const OdometryCalibrationResult r = solve_drive(spec);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.radius_scale, 1.01, 0.001 * 1.01);
  EXPECT_NEAR(r.geometry_scale, 1.02, 0.001 * 1.02);
  EXPECT_GT(r.covariance(0, 0), 0.0);
  EXPECT_LT(std::abs(r.radius_scale - 1.01), 4.0 * std::sqrt(r.covariance(0, 0)));
  EXPECT_LT(std::abs(r.geometry_scale - 1.02), 4.0 * std::sqrt(r.covariance(1, 1)));
}

TEST(OdometryCalibrationDirect, RecoversRadiusAndGeometryScalesFromEveryFix) {
  const test::SyntheticDriveSpec spec = test::brief_spec(1.01, 1.02);
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  const OdometryCalibrationResult r = calibrate_odometry_direct(
      drive, spec.nominal, spec.nominal.robot_T_laser, spec.truth.robot_T_laser, 4.0);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.radius_scale, 1.01, 0.001 * 1.01);
  EXPECT_NEAR(r.geometry_scale, 1.02, 0.001 * 1.02);
  EXPECT_GT(r.covariance(0, 0), 0.0);
}

TEST(OdometryCalibrationDirect, EncoderOdometryIntegratesTheNominalKinematics) {
  RobotConfig robot;
  const MecanumKinematics kinematics(robot);
  const WheelArray angle = kinematics.inverse(BodyTwist{1.0, 0.0, 0.0});  // 1 m forward
  const double ticks_per_rad = robot.encoder_ticks_per_rev / (2.0 * M_PI);
  EncoderSample a{0, {0, 0, 0, 0}}, b{1'000'000, {}};
  for (size_t w = 0; w < 4; ++w) b.ticks[w] = static_cast<int32_t>(std::lround(angle[w] * ticks_per_rad));
  const std::vector<TimedPose> odom = encoder_odometry({a, b}, robot);
  ASSERT_EQ(odom.size(), 2u);
  EXPECT_NEAR(odom[1].pose.x, 1.0, 1e-4);
  EXPECT_NEAR(odom[1].pose.y, 0.0, 1e-9);
}

TEST(OdometryCalibration, ANominalRobotComesOutUnscaled) {
  test::SyntheticDriveSpec spec = test::brief_spec(1.0, 1.0);
  spec.nominal.robot_T_laser = spec.truth.robot_T_laser;
  const OdometryCalibrationResult r = solve_drive(spec);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.radius_scale, 1.0, 0.001);
  EXPECT_NEAR(r.geometry_scale, 1.0, 0.001);
}

TEST(OdometryCalibration, ScalesCorrectTheRobotFileKeepingTheLxLyRatio) {
  RobotConfig nominal;
  const RobotConfig fixed = corrected_robot(nominal, 1.01, 1.02);
  EXPECT_NEAR(fixed.wheel_radius, nominal.wheel_radius * 1.01, 1e-15);
  EXPECT_NEAR(fixed.half_wheelbase_lx + fixed.half_track_ly,
              1.02 * (nominal.half_wheelbase_lx + nominal.half_track_ly), 1e-15);
  EXPECT_NEAR(fixed.half_wheelbase_lx / fixed.half_track_ly,
              nominal.half_wheelbase_lx / nominal.half_track_ly, 1e-12);
}

TEST(OdometryCalibration, IntegratedScaledStepsTurnBySrOverSk) {
  const std::vector<BodyTwist> steps(100, BodyTwist{0.0, 0.0, 0.01});
  EXPECT_NEAR(integrate_scaled(steps, 1.01, 1.02).theta, 1.0 * 1.01 / 1.02, 1e-12);
}

TEST(OdometryCalibration, RefusesADriveThatDoesNotTurn) {
  std::vector<OdometryWindow> windows(40);
  for (OdometryWindow& w : windows) {
    w.nominal_steps.assign(10, BodyTwist{0.02, 0.0, 0.0});
    w.laser_first_T_last.pose = Pose2{0.2, 0.0, 0.0};
    w.laser_first_T_last.covariance = Eigen::Matrix3d::Identity() * 1e-6;
  }
  const OdometryCalibrationResult r = calibrate_odometry(windows, OdometryCalibrationOptions{});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("not observable"), std::string::npos) << r.message;
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
