#pragma once
// A mission file (deploy/config/mission_*.json, tests/ops/data/*.json): the waypoints
// in the map frame and how precisely, how fast and within how long to reach them.
// Every key but the waypoints has a default; errors name the file and the key.

#include "common/se2.hpp"

#include <cmath>
#include <string>
#include <vector>

namespace refloc {

struct Mission {
  std::vector<Pose2> waypoints;                       ///< /waypoints/i/{x_m, y_m, theta_deg}, map frame
  double xy_tolerance_m = 0.010;                      ///< /xy_tolerance_m [m]
  double heading_tolerance_rad = 0.5 * M_PI / 180.0;  ///< /heading_tolerance_deg [deg in the file]
  double max_speed_m_s = 1.0;                         ///< /max_speed_m_s [m/s]
  double timeout_s = 300.0;                           ///< /timeout_s: driving longer aborts the mission [s]
  double localization_timeout_s = 60.0;  ///< /localization_timeout_s: no POSE OK by then: exit 1 [s]
};

/// Reads and validates a mission file; throws ConfigError naming file and key.
Mission load_mission(const std::string& path);

class JsonConfig;
/// The same on a document already loaded (records every key for the reference); does not call
/// reject_unknown_keys.
Mission parse_mission(const JsonConfig& config);

}  // namespace refloc
