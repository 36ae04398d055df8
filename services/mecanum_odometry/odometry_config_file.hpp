#pragma once
// mecanum_odometry's config file (deploy/config/mecanum_odometry.json). Every
// key is optional with the default of the struct it fills; section "odometry" is
// OdometryConfig. Wheel geometry and the noise model are the robot's (robot.json).

#include "mecanum_odometry/mecanum_odometry.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct OdometryServiceConfig {
  OdometryConfig odometry;
  double slip_warning = 0.05;  ///< slip indicator counted as a slip event above this [m/s]
  std::string input_channel = "WHEEL_ENCODERS";
  std::string output_channel = "ODOMETRY";
};

/// The whole file; call config.reject_unknown_keys() afterwards.
OdometryServiceConfig parse_odometry_service_config(const JsonConfig& config);

/// Load, parse and reject unknown keys; "" gives the defaults.
OdometryServiceConfig load_odometry_service_config(const std::string& path);

}  // namespace refloc
