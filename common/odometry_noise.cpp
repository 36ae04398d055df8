#include "common/odometry_noise.hpp"

#include "common/json_config.hpp"

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

OdometryNoise parse_odometry_noise(const JsonConfig& config, const std::string& p) {
  OdometryNoise n;
  n.translation_variance_per_m =
      config.number(p + "/translation_variance_m2_per_m", n.translation_variance_per_m, 0.0, 1.0);
  n.heading_variance_per_m =
      config.number(p + "/heading_variance_rad2_per_m", n.heading_variance_per_m, 0.0, 1.0);
  n.heading_variance_per_rad =
      config.number(p + "/heading_variance_rad2_per_rad", n.heading_variance_per_rad, 0.0, 1.0);
  n.translation_variance_per_rad =
      config.number(p + "/translation_variance_m2_per_rad", n.translation_variance_per_rad, 0.0, 1.0);
  return n;
}

}  // namespace refloc
