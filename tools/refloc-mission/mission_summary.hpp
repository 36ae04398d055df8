#pragma once
// refloc-mission's output: lines for a terminal (and the scripts that grep them) for a
// goal sent, a waypoint reached and the summary at the end; the JSON report and the plot's trace.

#include "mission_monitor.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace refloc {

/// "sent mission <id>" for the first goal, "resending waypoints a..b as goal <id> ..." after.
std::string format_goal_sent(const GoalRequest& goal, size_t nwaypoints);

/// "waypoint <i> reached: true error <mm> mm, <deg> deg".
std::string format_waypoint_reached(size_t index, const WaypointResult& result);

/// Waypoints reached, the largest true waypoint error, POSE and LASER_POSE RMSE and NEES,
/// pose_solver's range bias, the odometry drift and an abort reason, from MissionMonitor::report().
std::string format_mission_summary(const nlohmann::json& report);

/// Where refloc-mission writes its results (empty: not written).
struct MissionFiles {
  std::string json_file;  ///< MissionMonitor::report()
  std::string log_file;   ///< the LCM log recorded alongside: named in the JSON
  /// CSV for tools/refloc-plot (path_plot_trace.hpp); default <log_file>.trace.csv when a log file is named
  std::string trace_file;
};

/// Writes the report and the plot's trace; returns the summary and the trace's path for the
/// terminal (or that it could not be written). Throws ConfigError when the JSON file cannot be written.
std::string write_mission_results(const MissionMonitor& monitor, const MissionFiles& files);

}  // namespace refloc
