#include "mecanum_odometry/odometry_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

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

OdometryServiceConfig parse_odometry_service_config(const JsonConfig& config) {
  OdometryServiceConfig c;
  c.odometry.noise = parse_odometry_noise(config, "/noise");
  c.odometry.max_gap = config.number("/max_gap_s", c.odometry.max_gap, 0.01, 60.0);
  c.odometry.max_plausible_wheel_speed =
      config.number("/max_plausible_wheel_speed_rad_s", c.odometry.max_plausible_wheel_speed, 1.0, 10000.0);
  c.slip_warning = config.number("/slip_warning_m_s", c.slip_warning, 0.0, 10.0);
  c.input_channel = config.string("/input_channel", c.input_channel);
  c.output_channel = config.string("/output_channel", c.output_channel);
  if (c.input_channel.empty()) config.fail("/input_channel", "expected a channel name, got \"\"");
  if (c.output_channel.empty()) config.fail("/output_channel", "expected a channel name, got \"\"");
  return c;
}

}  // namespace refloc
