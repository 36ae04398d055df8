#include "common/robot_config.hpp"

#include "common/json_config.hpp"

#include <cmath>

namespace refloc {

RobotConfig parse_robot_config(const JsonConfig& config, const std::string& pointer) {
  RobotConfig robot;
  const std::string& p = pointer;
  robot.wheel_radius = config.number(p + "/wheel_radius_m", robot.wheel_radius, 0.01, 1.0);
  robot.half_wheelbase_lx = config.number(p + "/half_wheelbase_lx_m", robot.half_wheelbase_lx, 0.01, 5.0);
  robot.half_track_ly = config.number(p + "/half_track_ly_m", robot.half_track_ly, 0.01, 5.0);
  robot.encoder_ticks_per_rev = static_cast<int>(
      config.integer(p + "/encoder_ticks_per_rev", robot.encoder_ticks_per_rev, 4, 100000000));
  robot.max_wheel_speed = config.number(p + "/max_wheel_speed_rad_s", robot.max_wheel_speed, 0.1, 1000.0);
  robot.max_wheel_accel = config.number(p + "/max_wheel_accel_rad_s2", robot.max_wheel_accel, 0.1, 10000.0);
  robot.robot_T_laser.x = config.number(p + "/laser_mount/x_m", robot.robot_T_laser.x, -5.0, 5.0);
  robot.robot_T_laser.y = config.number(p + "/laser_mount/y_m", robot.robot_T_laser.y, -5.0, 5.0);
  robot.robot_T_laser.theta =
      config.number(p + "/laser_mount/theta_rad", robot.robot_T_laser.theta, -M_PI, M_PI);
  robot.odometry_noise = parse_odometry_noise(config, p + "/odometry_noise");
  // A human-readable statement of the conventions; read only so it is a known key.
  config.string(p + "/wheel_order", "");
  return robot;
}

RobotConfig load_robot_config(const std::string& path) {
  const JsonConfig config = JsonConfig::load_file(path);
  RobotConfig robot = parse_robot_config(config);
  config.reject_unknown_keys();
  return robot;
}

}  // namespace refloc
