#pragma once
// The robot's geometry, drive limits and odometry noise (deploy/config/robot.json),
// shared by mecanum_odometry, pose_fusion, robot_sim, navigator and the pose solver
// (laser mount).
//
// Wheel order everywhere: front-left, front-right, rear-right, rear-left.
// Body frame: +x forward, +y left, +wz counter-clockwise. A positive wheel
// spin drives that wheel's contact point forward.

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct RobotConfig {
  double wheel_radius = 0.076;          ///< [m]
  double half_wheelbase_lx = 0.25;      ///< wheel centre to robot centre along x [m]
  double half_track_ly = 0.22;          ///< wheel centre to robot centre along y [m]
  int encoder_ticks_per_rev = 16384;    ///< ticks per wheel revolution (4096 * gear 4)
  double max_wheel_speed = 20.0;        ///< [rad/s]
  double max_wheel_accel = 20.0;        ///< [rad/s^2]
  Pose2 robot_T_laser{0.30, 0.0, 0.0};  ///< laser mount in the robot frame [m, m, rad]
  OdometryNoise odometry_noise;         ///< wheel-odometry increment noise (section "odometry_noise")
};

/// Read a RobotConfig from the object at pointer ("" = root) of a loaded document.
/// Every key has the default above; values are range-checked (ConfigError on error).
RobotConfig parse_robot_config(const JsonConfig& config, const std::string& pointer = "");

/// Load robot.json, validate, and reject unknown keys.
RobotConfig load_robot_config(const std::string& path);

}  // namespace refloc
