#include "mount_calibration.hpp"
#include "mount_direct.hpp"
#include "synthetic_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;

MountCalibrationResult solve_brief_drive(double radius_factor, double geometry_factor, unsigned seed) {
  test::SyntheticDriveSpec spec = test::brief_spec(radius_factor, geometry_factor);
  spec.seed = seed;
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  MountCalibrationOptions o;
  o.initial_robot_T_laser = spec.nominal.robot_T_laser;
  o.odometry_noise = spec.nominal.odometry_noise;
  return calibrate_mount(mount_windows(drive, spec.nominal.robot_T_laser, WindowOptions{}), o);
}

TEST(MountCalibration, RecoversTheBriefsMountWithinTwoMillimetresAndFiveHundredthsOfADegree) {
  const MountCalibrationResult r = solve_brief_drive(1.0, 1.0, 7);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.robot_T_laser.x, 0.35, 0.002);
  EXPECT_NEAR(r.robot_T_laser.y, -0.12, 0.002);
  EXPECT_NEAR(r.robot_T_laser.theta, 1.5 * kDeg, 0.05 * kDeg);
  EXPECT_NEAR(r.translation_scale, 1.0, 0.002);
}

TEST(MountCalibration, WheelRadiusAndGeometryErrorsDoNotBiasTheMount) {
  // 1 % radius, 2 % lx + ly: odometry translations 1 % short, its rotations 1 % long.
  const MountCalibrationResult r = solve_brief_drive(1.01, 1.02, 8);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.robot_T_laser.x, 0.35, 0.002);
  EXPECT_NEAR(r.robot_T_laser.y, -0.12, 0.002);
  EXPECT_NEAR(r.robot_T_laser.theta, 1.5 * kDeg, 0.05 * kDeg);
  EXPECT_NEAR(r.translation_scale, 1.01, 0.002);
}

TEST(MountCalibration, SigmaCoversTheErrorOverSeeds) {
  int inside = 0;
  const int runs = 10;
  for (int seed = 0; seed < runs; ++seed) {
    const MountCalibrationResult r = solve_brief_drive(1.0, 1.0, 100 + static_cast<unsigned>(seed));
    ASSERT_TRUE(r.ok) << r.message;
    EXPECT_GT(r.covariance(0, 0), 0.0);
    const bool x_in = std::abs(r.robot_T_laser.x - 0.35) < 3.0 * std::sqrt(r.covariance(0, 0));
    const bool y_in = std::abs(r.robot_T_laser.y + 0.12) < 3.0 * std::sqrt(r.covariance(1, 1));
    const bool t_in = std::abs(r.robot_T_laser.theta - 1.5 * kDeg) < 3.0 * std::sqrt(r.covariance(2, 2));
    inside += (x_in && y_in && t_in) ? 1 : 0;
  }
  EXPECT_GE(inside, runs - 1);
}

MountCalibrationResult solve_direct(double radius_factor, double geometry_factor) {
  const test::SyntheticDriveSpec spec = test::brief_spec(radius_factor, geometry_factor);
  const CalibrationDrive drive = test::make_synthetic_drive(spec);
  DirectMountOptions o;
  o.mount.initial_robot_T_laser = spec.nominal.robot_T_laser;
  o.mount.odometry_noise = spec.nominal.odometry_noise;
  return calibrate_mount_direct(drive, spec.nominal.robot_T_laser, o);
}

TEST(MountCalibrationDirect, RecoversTheBriefsMountUsingEveryFix) {
  const MountCalibrationResult r = solve_direct(1.0, 1.0);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.robot_T_laser.x, 0.35, 0.001);
  EXPECT_NEAR(r.robot_T_laser.y, -0.12, 0.001);
  EXPECT_NEAR(r.robot_T_laser.theta, 1.5 * kDeg, 0.02 * kDeg);
  EXPECT_LT(std::abs(r.robot_T_laser.x - 0.35), 4.0 * std::sqrt(r.covariance(0, 0)));
  EXPECT_LT(std::abs(r.robot_T_laser.theta - 1.5 * kDeg), 4.0 * std::sqrt(r.covariance(2, 2)));
}

TEST(MountCalibrationDirect, WheelErrorsStayWithinTheBriefsTolerance) {
  // The scaled odometry (s on translation, h on heading) is exact on straight legs and in
  // place, approximate on arcs: there a 1 % heading error bends the chained translation.
  const MountCalibrationResult r = solve_direct(1.01, 1.02);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_NEAR(r.robot_T_laser.x, 0.35, 0.002);
  EXPECT_NEAR(r.robot_T_laser.y, -0.12, 0.002);
  EXPECT_NEAR(r.robot_T_laser.theta, 1.5 * kDeg, 0.05 * kDeg);
  EXPECT_NEAR(r.translation_scale, 1.01, 0.001);
}

TEST(MountCalibration, RefusesADriveWithoutRotationNamingWhy) {
  std::vector<MountWindow> windows(50);
  for (MountWindow& w : windows) {
    w.odometry_first_T_last = Pose2{0.2, 0.0, 0.0};
    w.laser_first_T_last.pose = Pose2{0.2, 0.0, 0.0};
    w.laser_first_T_last.covariance = Eigen::Matrix3d::Identity() * 1e-6;
  }
  const MountCalibrationResult r = calibrate_mount(windows, MountCalibrationOptions{});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("rotate in place"), std::string::npos) << r.message;
}

TEST(MountCalibration, RefusesADriveWithoutStraightLegsNamingWhy) {
  std::vector<MountWindow> windows(50);
  for (MountWindow& w : windows) {
    w.laser_first_T_last.pose = Pose2{0.0, 0.0, 0.3};
    w.laser_first_T_last.covariance = Eigen::Matrix3d::Identity() * 1e-6;
  }
  const MountCalibrationResult r = calibrate_mount(windows, MountCalibrationOptions{});
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.message.find("straight legs"), std::string::npos) << r.message;
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
