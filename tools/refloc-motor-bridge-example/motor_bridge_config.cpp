#include "motor_bridge_config.hpp"

#include "common/json_config.hpp"

namespace refloc {

MotorBridgeConfig parse_motor_bridge_config(const JsonConfig& config) {
  MotorBridgeConfig c;
  c.command_timeout_s = config.number({"/command_timeout_s", "s",
                                       "stop the wheels when no CMD_VEL arrived for this long (navigator "
                                       "sends at 50 Hz; robot_sim uses 0.2)"},
                                      c.command_timeout_s, 0.02, 2.0);
  c.encoder_rate_hz = config.number(
      {"/encoder_rate_hz", "Hz",
       "WHEEL_ENCODERS rate; pose_fusion treats odometry older than its odometry_timeout_s (0.1) as silent"},
      c.encoder_rate_hz, 20.0, 1000.0);
  return c;
}

MotorBridgeConfig load_motor_bridge_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  MotorBridgeConfig config = parse_motor_bridge_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
