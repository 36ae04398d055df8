#pragma once
// How uncertain a wheel-odometry displacement is: variances grow linearly with
// the distance driven and the angle turned (a random-walk model per metre and
// per radian, as in the classic Borenstein/Thrun odometry models). A property of
// the robot, configured once in robot.json ("odometry_noise") and read by
// mecanum_odometry and pose_fusion alike.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <string>

namespace refloc {

class JsonConfig;

struct OdometryNoise {
  double translation_variance_per_m = 1e-4;    ///< [m^2 per m driven] (1 cm after 1 m)
  double heading_variance_per_m = 1e-5;        ///< [rad^2 per m driven]
  double heading_variance_per_rad = 2.5e-4;    ///< [rad^2 per rad turned]
  double translation_variance_per_rad = 1e-5;  ///< [m^2 per rad turned]
};

/// Covariance of a body-frame displacement delta (x, y, theta) [m^2, m rad, rad^2].
Eigen::Matrix3d increment_covariance(const Pose2& delta, const OdometryNoise& noise);

/// The noise coefficients from the object at pointer (keys translation_variance_m2_per_m,
/// heading_variance_rad2_per_m, heading_variance_rad2_per_rad, translation_variance_m2_per_rad).
OdometryNoise parse_odometry_noise(const JsonConfig& config, const std::string& pointer);

}  // namespace refloc
