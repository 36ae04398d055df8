#include "mecanum_odometry/odometry_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

OdometryServiceConfig parse_odometry_service_config(const JsonConfig& config) {
  OdometryServiceConfig c;
  c.odometry.max_gap = config.number(
      {"/odometry/max_gap_s", "s",
       "samples further apart than this restart integration from the new counts (gap_restarts): the "
       "gap's motion is lost; longer integrates a long gap as one arc, or a counter reset as a jump"},
      c.odometry.max_gap, 0.01, 60.0);
  c.odometry.max_plausible_wheel_speed = config.number(
      {"/odometry/max_plausible_wheel_speed_rad_s", "rad/s",
       "a sample with a wheel faster than this is a counter glitch: skipped, its motion lost, twist 0 "
       "(implausible_samples); keep well above robot.json max_wheel_speed_rad_s"},
      c.odometry.max_plausible_wheel_speed, 1.0, 10000.0);
  c.slip_warning = config.positive_number(
      {"/slip_warning_m_s", "m/s",
       "wheels disagreeing on one rigid motion faster than this (residual of the 4th kinematic "
       "equation) count a slip_samples in HEARTBEAT; a counter only, the odometry is unchanged"},
      c.slip_warning, 10.0, "0 would report slip on every sample");
  c.input_channel = config.string(
      {"/input_channel", "",
       "LCM channel of the four cumulative wheel encoder counts read (wheel_encoders_t), from the "
       "motor bridge or robot_sim"},
      c.input_channel);
  c.output_channel = config.string(
      {"/output_channel", "",
       "LCM channel the odometry is published on (odometry_t: odom-frame pose, body twist, covariance, "
       "slip), one per accepted sample; pose_fusion and reflector_extractor read it"},
      c.output_channel);
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
