#include "mecanum_odometry/odometry_covariance.hpp"

#include <cmath>

namespace refloc {

Eigen::Matrix3d increment_covariance(const Pose2& delta, const OdometryNoise& noise) {
  const double distance = std::hypot(delta.x, delta.y);
  const double turn = std::abs(delta.theta);
  const double var_xy =
      noise.translation_variance_per_m * distance + noise.translation_variance_per_rad * turn;
  const double var_theta = noise.heading_variance_per_m * distance + noise.heading_variance_per_rad * turn;
  return Eigen::Vector3d(var_xy, var_xy, var_theta).asDiagonal();
}

Eigen::Matrix3d compose_covariance(const Pose2& x, const Eigen::Matrix3d& p, const Pose2& delta,
                                   const Eigen::Matrix3d& q) {
  const double c = std::cos(x.theta), s = std::sin(x.theta);
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();  // d(x * delta) / dx
  f(0, 2) = -s * delta.x - c * delta.y;
  f(1, 2) = c * delta.x - s * delta.y;
  Eigen::Matrix3d g = Eigen::Matrix3d::Identity();  // d(x * delta) / d delta
  g(0, 0) = c;
  g(0, 1) = -s;
  g(1, 0) = s;
  g(1, 1) = c;
  return f * p * f.transpose() + g * q * g.transpose();
}

}  // namespace refloc
