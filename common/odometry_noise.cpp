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
  n.translation_variance_per_m = config.number(
      {p + "/translation_variance_m2_per_m", "m^2/m",
       "x and y variance added per metre driven (1e-4: 1 cm sigma after 1 m); too small: pose_fusion's gate "
       "refuses good fixes, too large: POSE follows every fix's noise"},
      n.translation_variance_per_m, 0.0, 1.0);
  n.heading_variance_per_m = config.number(
      {p + "/heading_variance_rad2_per_m", "rad^2/m",
       "heading variance added per metre driven (1e-5: 0.18 deg sigma after 1 m): heading drift while "
       "driving straight"},
      n.heading_variance_per_m, 0.0, 1.0);
  n.heading_variance_per_rad = config.number(
      {p + "/heading_variance_rad2_per_rad", "rad^2/rad",
       "heading variance added per radian turned (2.5e-4: 0.9 deg sigma after 1 rad); raise if fixes are "
       "refused (fixes_rejected_gate) after turns"},
      n.heading_variance_per_rad, 0.0, 1.0);
  n.translation_variance_per_rad = config.number(
      {p + "/translation_variance_m2_per_rad", "m^2/rad",
       "x and y variance added per radian turned (1e-5: 3 mm sigma after 1 rad): wheel slip while turning on "
       "the spot"},
      n.translation_variance_per_rad, 0.0, 1.0);
  return n;
}

}  // namespace refloc
