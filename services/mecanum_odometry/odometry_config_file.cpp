#include "mecanum_odometry/odometry_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

OdometryServiceConfig parse_odometry_service_config(const JsonConfig& config) {
  OdometryServiceConfig c;
  c.odometry.max_gap = config.number("/odometry/max_gap_s", c.odometry.max_gap, 0.01, 60.0);
  c.odometry.max_plausible_wheel_speed = config.number("/odometry/max_plausible_wheel_speed_rad_s",
                                                       c.odometry.max_plausible_wheel_speed, 1.0, 10000.0);
  c.slip_warning = config.positive_number("/slip_warning_m_s", c.slip_warning, 10.0,
                                          "0 would report slip on every sample");
  c.input_channel = config.string("/input_channel", c.input_channel);
  c.output_channel = config.string("/output_channel", c.output_channel);
  if (c.input_channel.empty()) config.fail("/input_channel", "expected a channel name, got \"\"");
  if (c.output_channel.empty()) config.fail("/output_channel", "expected a channel name, got \"\"");
  return c;
}

OdometryServiceConfig load_odometry_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  OdometryServiceConfig config = parse_odometry_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
