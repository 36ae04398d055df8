#pragma once
// How uncertain a wheel-odometry displacement is: variances grow linearly with
// the distance driven and the angle turned (a random-walk model per metre and
// per radian, as in the classic Borenstein/Thrun odometry models).

#include "common/se2.hpp"

#include <Eigen/Core>

namespace refloc {

struct OdometryNoise {
  double translation_variance_per_m = 1e-4;    ///< [m^2 per m driven] (1 cm after 1 m)
  double heading_variance_per_m = 1e-5;        ///< [rad^2 per m driven]
  double heading_variance_per_rad = 2.5e-4;    ///< [rad^2 per rad turned]
  double translation_variance_per_rad = 1e-5;  ///< [m^2 per rad turned]
};

/// Covariance of a body-frame displacement delta (x, y, theta) [m^2, m rad, rad^2].
Eigen::Matrix3d increment_covariance(const Pose2& delta, const OdometryNoise& noise);

/// Propagate the covariance of a pose P(x) through x' = x * delta, where delta
/// has covariance q in the body frame of x. Returns P(x').
Eigen::Matrix3d compose_covariance(const Pose2& x, const Eigen::Matrix3d& p, const Pose2& delta,
                                   const Eigen::Matrix3d& q);

}  // namespace refloc
