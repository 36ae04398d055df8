#pragma once
// navigator's config file (deploy/config/navigator.json). Every key is
// optional with the default of the struct it fills; the sections mirror the
// structs: "navigator" is NavigatorConfig, its "translation" and "rotation" the
// two ProfileLimits (rotation in rad, its creep_distance in degrees).

#include "navigator/navigator.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct NavigatorServiceConfig {
  NavigatorConfig navigator;
  double control_rate = 50.0;  ///< CMD_VEL rate [Hz]
  double status_rate = 10.0;   ///< NAV_STATUS rate besides every change [Hz]
  std::string goal_channel = "NAV_GOAL";
  std::string pose_channel = "POSE";
  std::string command_channel = "CMD_VEL";
  std::string status_channel = "NAV_STATUS";
};

/// The whole file; call config.reject_unknown_keys() afterwards.
NavigatorServiceConfig parse_navigator_service_config(const JsonConfig& config);

/// Load, parse and reject unknown keys; "" gives the defaults.
NavigatorServiceConfig load_navigator_service_config(const std::string& path);

}  // namespace refloc
