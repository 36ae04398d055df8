#include "common/robot_config.hpp"

#include "common/json_config.hpp"

#include <cmath>

namespace refloc {

RobotConfig parse_robot_config(const JsonConfig& config, const std::string& pointer) {
  RobotConfig robot;
  const std::string& p = pointer;
  robot.wheel_radius = config.number(
      {p + "/wheel_radius_m", "m",
       "effective rolling radius of a Mecanum wheel: scales every odometry distance and turn (1 % off: 1 cm "
       "per metre); refloc-calibrate-odometry measures it"},
      robot.wheel_radius, 0.01, 1.0);
  robot.half_wheelbase_lx = config.number(
      {p + "/half_wheelbase_lx_m", "m",
       "robot centre to wheel centre along x; only lx + ly enters the kinematics: odometry turn angles "
       "scale with 1/(lx + ly)"},
      robot.half_wheelbase_lx, 0.01, 5.0);
  robot.half_track_ly = config.number(
      {p + "/half_track_ly_m", "m",
       "robot centre to wheel centre along y; only lx + ly counts (refloc-calibrate-odometry measures the "
       "sum, keeping the ratio)"},
      robot.half_track_ly, 0.01, 5.0);
  robot.encoder_ticks_per_rev = static_cast<int>(config.integer(
      {p + "/encoder_ticks_per_rev", "count",
       "encoder counts per wheel revolution, gearbox included (4096 x gear 4); wrong: every odometry "
       "distance and turn off by the same factor"},
      robot.encoder_ticks_per_rev, 4, 100000000));
  robot.max_wheel_speed = config.number(
      {p + "/max_wheel_speed_rad_s", "rad/s",
       "wheel speed limit: robot_sim and the example bridge scale a faster command's four wheels down "
       "together (direction kept); the navigator does not read it"},
      robot.max_wheel_speed, 0.1, 1000.0);
  robot.max_wheel_accel = config.number(
      {p + "/max_wheel_accel_rad_s2", "rad/s^2",
       "wheel acceleration limit of robot_sim's simulated drive only (also how fast it stops on a stale "
       "command)"},
      robot.max_wheel_accel, 0.1, 10000.0);
  robot.robot_T_laser.x = config.number(
      {p + "/laser_mount/x_m", "m",
       "robot_T_laser: the laser's measurement origin ahead (+) of the robot centre (docs/real-robot.md "
       "§3); eq. 8's OO' = hypot(x_m, y_m); refloc-calibrate-mount"},
      robot.robot_T_laser.x, -5.0, 5.0);
  robot.robot_T_laser.y = config.number(
      {p + "/laser_mount/y_m", "m",
       "robot_T_laser: the laser's measurement origin left (+) of the robot centre; eq. 8's beta = "
       "-atan2(-y_m, -x_m)"},
      robot.robot_T_laser.y, -5.0, 5.0);
  robot.robot_T_laser.theta = config.number(
      {p + "/laser_mount/theta_rad", "rad",
       "robot_T_laser: the laser's straight ahead (90 deg in the LMS100's own angles) counter-clockwise (+) "
       "of the robot's forward; paper mode takes it off the heading before eq. 8"},
      robot.robot_T_laser.theta, -M_PI, M_PI);
  robot.odometry_noise = parse_odometry_noise(config, p + "/odometry_noise");
  // A human-readable statement of the conventions; read only so it is a known key.
  config.string({p + "/wheel_order", "",
                 "a note for people, not interpreted: ticks[0..3] are always front-left, front-right, "
                 "rear-right, rear-left (common/mecanum_kinematics.hpp)"},
                "");
  return robot;
}

RobotConfig load_robot_config(const std::string& path) {
  const JsonConfig config = JsonConfig::load_file(path);
  RobotConfig robot = parse_robot_config(config);
  config.reject_unknown_keys();
  return robot;
}

}  // namespace refloc
