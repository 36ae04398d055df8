// The scans' time offset in the state (model/estimate_scan_time_offset): a scan stamped a little
// late while the robot turns shifts all its detections along the laser's motion, the same way scan
// after scan. Taken as exact, the stamps make the filter publish a heading covariance far too
// small; with the offset in the state it is learned, and a robot standing still loses nothing.

#include "pose_fusion/pose_ekf.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 100'000'000;
constexpr int64_t kOdometryPeriod = 10'000;  // 100 Hz
const Pose2 kMount{0.3, 0.0, 0.0};

/// A robot on a circle: 0.5 m/s forward, turning at yaw_rate [rad/s], from (0, 0) heading +x.
struct Circle {
  double speed = 0.5;
  double yaw_rate = 1.0;
  Pose2 at(int64_t utime) const {
    const double t = static_cast<double>(utime - kT0) * 1e-6;
    return se2_exp({speed, 0.0, yaw_rate}, t);
  }
};

std::vector<Eigen::Vector2d> ring_of_reflectors() {
  std::vector<Eigen::Vector2d> out;
  for (int i = 0; i < 12; ++i) {
    const double a = 2.0 * M_PI * i / 12.0;
    out.emplace_back(6.0 * std::cos(a), 0.5 + 6.0 * std::sin(a));
  }
  return out;
}

struct DriveOutcome {
  double position_nees = 0.0;  ///< mean over the second half
  double heading_nees = 0.0;
  double rmse_m = 0.0;
};

/// 20 s on the circle; each scan measured lag_s after the time it is stamped with.
DriveOutcome drive(const Circle& circle, double lag_s, bool estimate_offset, uint32_t seed,
                   double* offset_estimate_s = nullptr) {
  FusionConfig config;
  config.model.robot_T_laser = kMount;
  config.model.estimate_scan_time_offset = estimate_offset;
  config.model.estimate_odometry_error = false;
  PoseFusion fusion(config);
  const std::vector<Eigen::Vector2d> reflectors = ring_of_reflectors();
  std::mt19937 rng(seed);
  constexpr double kSigma = 0.003;
  std::normal_distribution<double> noise(0.0, kSigma);
  fusion.add_odometry(kT0, {}, Eigen::Matrix3d::Zero());
  fusion.add_fix({kT0, circle.at(kT0), Eigen::Vector3d(1e-6, 1e-6, 1e-7).asDiagonal(), FixQuality::kGood});
  const Eigen::Matrix3d q = Eigen::Vector3d(1e-8, 1e-8, 1e-8).asDiagonal();
  DriveOutcome run;
  double nees_sum = 0.0, heading_nees_sum = 0.0, error_sum = 0.0;
  int n = 0;
  const int steps = 2000;
  for (int k = 1; k <= steps; ++k) {
    const int64_t t = kT0 + k * kOdometryPeriod;
    fusion.add_odometry(t, circle.at(t - kOdometryPeriod).inverse() * circle.at(t), q);
    if (k % 2 == 0) {
      const auto measured_at = t + static_cast<int64_t>(std::llround(lag_s * 1e6));
      const Pose2 map_T_laser = circle.at(measured_at) * kMount;
      DetectionScan scan;
      scan.utime = t;
      int id = 0;
      for (const Eigen::Vector2d& m : reflectors) {
        const Eigen::Vector2d z = map_T_laser.inverse() * m + Eigen::Vector2d(noise(rng), noise(rng));
        scan.detections.push_back({z, Eigen::Matrix2d::Identity() * kSigma * kSigma, m, ++id});
      }
      fusion.add_detections(scan);
    }
    if (k > steps / 2) {
      const PoseEstimate e = fusion.estimate();
      const Pose2 g = circle.at(t);
      const Eigen::Vector2d d(e.map_T_robot.x - g.x, e.map_T_robot.y - g.y);
      nees_sum += d.dot(e.covariance.topLeftCorner<2, 2>().ldlt().solve(d));
      error_sum += d.squaredNorm();
      const double dh = angle_diff(e.map_T_robot.theta, g.theta);
      heading_nees_sum += dh * dh / e.covariance(2, 2);
      ++n;
    }
  }
  run.position_nees = nees_sum / n;
  run.rmse_m = std::sqrt(error_sum / n);
  run.heading_nees = heading_nees_sum / n;
  if (offset_estimate_s != nullptr) *offset_estimate_s = fusion.state().scan_time_offset_s;
  return run;
}

TEST(ScanTiming, PointRateIsTheDerivativeOfTheLaserFramePoint) {
  const Circle circle;
  const Eigen::Vector2d m(4.0, 3.0);
  const int64_t t = kT0 + 1'234'567;
  const Pose2 robot = circle.at(t);
  ScanTiming timing;
  // The laser's own twist: the robot's (0.5, 0, 1) moved to the mount at (0.3, 0).
  timing.laser_velocity = {circle.speed, circle.yaw_rate * kMount.x};
  timing.yaw_rate = circle.yaw_rate;
  const Eigen::Vector2d z = (robot * kMount).inverse() * m;
  const int64_t h_us = 100;
  const Eigen::Vector2d numeric =
      ((circle.at(t + h_us) * kMount).inverse() * m - (circle.at(t - h_us) * kMount).inverse() * m) /
      (2e-6 * h_us);
  EXPECT_LT((laser_point_rate(z, timing) - numeric).norm(), 1e-4) << numeric.transpose();
}

TEST(ScanTiming, ScansLateWhileTurningAreHonestOnlyWithTheOffsetInTheState) {
  const Circle circle;
  const DriveOutcome exact_stamps = drive(circle, 0.001, false, 1);
  double offset_s = 0.0;
  const DriveOutcome estimated = drive(circle, 0.001, true, 1, &offset_s);
  std::printf(
      "scans 1 ms late, turning at 1 rad/s: position NEES %.1f, heading NEES %.1f (RMSE %.2f mm) with "
      "stamps taken as exact; %.2f, %.2f (%.2f mm) with the offset estimated (%.3f ms)\n",
      exact_stamps.position_nees, exact_stamps.heading_nees, 1e3 * exact_stamps.rmse_m,
      estimated.position_nees, estimated.heading_nees, 1e3 * estimated.rmse_m, 1e3 * offset_s);
  EXPECT_GT(exact_stamps.heading_nees, 20.0);
  EXPECT_LT(estimated.heading_nees, 2.0);
  EXPECT_LT(estimated.position_nees, 3.0);
  EXPECT_NEAR(offset_s, 0.001, 0.0004);  // a constant turn tells the offset from a heading error slowly
}

TEST(ScanTiming, StandingStillTheOffsetChangesNothing) {
  Circle standing;
  standing.speed = 0.0;
  standing.yaw_rate = 0.0;
  const DriveOutcome exact_stamps = drive(standing, 0.001, false, 2);
  const DriveOutcome estimated = drive(standing, 0.001, true, 2);
  EXPECT_NEAR(estimated.rmse_m, exact_stamps.rmse_m, 1e-9);
  EXPECT_NEAR(estimated.position_nees, exact_stamps.position_nees, 1e-6);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
