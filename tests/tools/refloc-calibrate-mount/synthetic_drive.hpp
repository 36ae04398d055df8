#pragma once
// A calibration drive with known truth for the calibration tools' tests: a true robot (mount,
// wheel radius, lx + ly) drives a fixed twist profile (rotation in place, straight legs,
// sideways, an arc; ~53 s); encoders count the true wheel angles at 100 Hz, odometry integrates
// them with the nominal robot, laser fixes at 50 Hz are the true laser pose with noise written
// as LASER_POSE is (map_T_robot with the configured mount).

#include "calibration_pairs.hpp"
#include "common/mecanum_kinematics.hpp"
#include "common/robot_config.hpp"

#include <cmath>
#include <random>
#include <vector>

namespace refloc::test {
namespace {

struct SyntheticDriveSpec {
  RobotConfig nominal;  ///< what the services are configured with
  RobotConfig truth;    ///< what the robot is
  double fix_sigma_m = 0.003;
  double fix_sigma_rad = 0.0005;
  /// Correlation of consecutive fixes' errors (AR(1) coefficient; 0: independent). The marginal
  /// sigma stays fix_sigma_*.
  double fix_correlation = 0.0;
  unsigned seed = 7;
};

struct TimedTwist {
  BodyTwist twist;
  double duration_s;
};

inline std::vector<TimedTwist> calibration_profile() {
  return {{{0.0, 0.0, 0.6}, 10.5}, {{0.4, 0.0, 0.0}, 5.0},  {{0.0, 0.0, -0.6}, 5.2}, {{0.0, 0.3, 0.0}, 4.0},
          {{-0.4, 0.0, 0.0}, 5.0}, {{0.0, 0.0, 0.6}, 10.5}, {{0.3, 0.0, 0.2}, 8.0},  {{0.0, -0.3, 0.0}, 4.0}};
}

inline CalibrationDrive make_synthetic_drive(const SyntheticDriveSpec& spec) {
  const MecanumKinematics true_kinematics(spec.truth);
  const MecanumKinematics nominal_kinematics(spec.nominal);
  std::mt19937 rng(spec.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  CalibrationDrive drive;
  const int64_t step_us = 1000;  // 1 kHz truth
  int64_t utime = 1'000'000'000;
  Pose2 map_T_robot{3.0, 3.0, 0.3};
  std::array<double, 4> wheel_rad{};
  Pose2 odom_T_robot;
  EncoderSample last_encoder{utime, {2147000000, 2147000000, 2147000000, 2147000000}};  // wraps soon
  drive.encoders.push_back(last_encoder);
  drive.odometry.push_back({utime, odom_T_robot, Eigen::Matrix3d::Zero()});
  const double tick_per_rad = spec.nominal.encoder_ticks_per_rev / (2.0 * M_PI);
  std::array<double, 4> start_ticks{};
  for (size_t w = 0; w < 4; ++w) start_ticks[w] = last_encoder.ticks[w];
  int64_t k = 0;
  Eigen::Vector3d fix_error = Eigen::Vector3d::Zero();
  const double innovation = std::sqrt(1.0 - spec.fix_correlation * spec.fix_correlation);
  for (const TimedTwist& segment : calibration_profile()) {
    const auto steps = static_cast<int64_t>(std::lround(segment.duration_s * 1e6 / step_us));
    for (int64_t i = 0; i < steps; ++i, ++k) {
      utime += step_us;
      const double dt = step_us * 1e-6;
      const WheelArray w = true_kinematics.inverse(segment.twist);
      for (size_t j = 0; j < 4; ++j) wheel_rad[j] += w[j] * dt;
      map_T_robot = map_T_robot * se2_exp(segment.twist, dt);
      if (k % 10 == 9) {  // 100 Hz encoders and odometry
        EncoderSample e{utime, {}};
        for (size_t j = 0; j < 4; ++j) {
          const auto ticks = static_cast<int64_t>(std::floor(start_ticks[j] + wheel_rad[j] * tick_per_rad));
          e.ticks[j] = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(ticks)));
        }
        const auto angle = wheel_angle_delta(last_encoder, e, spec.nominal.encoder_ticks_per_rev);
        odom_T_robot = odom_T_robot * se2_exp(nominal_kinematics.forward(angle));
        drive.encoders.push_back(e);
        drive.odometry.push_back({utime, odom_T_robot, Eigen::Matrix3d::Zero()});
        last_encoder = e;
      }
      if (k % 20 == 13) {  // 50 Hz fixes, not on the encoder stamps
        Pose2 map_T_laser = map_T_robot * spec.truth.robot_T_laser;
        Eigen::Vector3d fresh;  // drawn in this order (x, y, theta): arguments' order is unspecified
        fresh.x() = spec.fix_sigma_m * unit(rng);
        fresh.y() = spec.fix_sigma_m * unit(rng);
        fresh.z() = spec.fix_sigma_rad * unit(rng);
        fix_error = drive.laser_fixes.empty() ? fresh : spec.fix_correlation * fix_error + innovation * fresh;
        map_T_laser.x += fix_error.x();
        map_T_laser.y += fix_error.y();
        map_T_laser.theta += fix_error.z();
        TimedPose fix{utime, map_T_laser * spec.nominal.robot_T_laser.inverse(), Eigen::Matrix3d::Zero()};
        // The solver's covariance is of map_T_robot; give the laser's, carried through the lever arm.
        TimedPose laser_with_cov{
            utime, map_T_laser,
            Eigen::Vector3d(spec.fix_sigma_m * spec.fix_sigma_m, spec.fix_sigma_m * spec.fix_sigma_m,
                            spec.fix_sigma_rad * spec.fix_sigma_rad)
                .asDiagonal()};
        fix.covariance = compose_mount(laser_with_cov, spec.nominal.robot_T_laser.inverse()).covariance;
        drive.laser_fixes.push_back(fix);
      }
    }
  }
  return drive;
}

/// The test's robot pair: the brief's mount (0.35, -0.12, 1.5 deg) against (0.30, -0.10, 0).
inline SyntheticDriveSpec brief_spec(double radius_factor, double geometry_factor) {
  SyntheticDriveSpec spec;
  spec.nominal.robot_T_laser = Pose2{0.30, -0.10, 0.0};
  spec.truth = spec.nominal;
  spec.truth.robot_T_laser = Pose2{0.35, -0.12, 1.5 * M_PI / 180.0};
  spec.truth.wheel_radius *= radius_factor;
  spec.truth.half_wheelbase_lx *= geometry_factor;
  spec.truth.half_track_ly *= geometry_factor;
  return spec;
}

}  // namespace
}  // namespace refloc::test
