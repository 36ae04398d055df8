#include "mission_summary.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <fstream>

namespace refloc {

std::string format_goal_sent(const GoalRequest& goal, size_t nwaypoints) {
  if (!goal.resend) return fmt::format("sent mission {}\n", goal.goal_id);
  return fmt::format("resending waypoints {}..{} as goal {} (navigator restarted or silent)\n",
                     goal.first_waypoint, nwaypoints - 1, goal.goal_id);
}

std::string format_waypoint_reached(size_t index, const WaypointResult& result) {
  return fmt::format("waypoint {} reached: true error {:.1f} mm, {:.2f} deg\n", index,
                     result.error_xy_m * 1000.0, result.error_heading_rad * 180.0 / M_PI);
}

namespace {

/// "<channel> NEES vs GROUND_TRUTH: position <mean> (2 if honest), <share> % outside 99 %; heading ...".
std::string format_nees(const std::string& channel, const nlohmann::json& nees) {
  return fmt::format(
      "{} NEES vs GROUND_TRUTH: position {:.2f} (honest: 2), {:.1f} % outside 99 %; heading {:.2f} "
      "(honest: 1), {:.1f} % outside 99 %; {} fixes ({} without a usable covariance)\n",
      channel, nees["position_nees_mean"].get<double>(),
      100.0 * nees["position_outside_99_percent"].get<double>(), nees["heading_nees_mean"].get<double>(),
      100.0 * nees["heading_outside_99_percent"].get<double>(), nees["nees_fixes"].get<int>(),
      nees["unusable_covariances"].get<int>());
}

}  // namespace

std::string format_mission_summary(const nlohmann::json& report) {
  std::string out = fmt::format("\nwaypoints reached: {}/{}\n", report["waypoints_reached"].get<size_t>(),
                                report["waypoints_total"].get<size_t>());
  out += fmt::format("max true waypoint error: {:.1f} mm, {:.2f} deg\n",
                     report["max_waypoint_error_mm"].get<double>(),
                     report["max_waypoint_heading_error_deg"].get<double>());
  out += fmt::format(
      "POSE RMSE vs GROUND_TRUTH: {:.1f} mm (max {:.1f} mm, {:.1f} mm while moving), heading {:.2f} mrad, "
      "over "
      "{} samples\n",
      report["pose_rmse_mm"].get<double>(), report["pose_max_error_mm"].get<double>(),
      report.value("pose_max_error_moving_mm", 0.0), report.value("pose_heading_rmse_mrad", 0.0),
      report["pose_samples"].get<size_t>());
  out += fmt::format("LASER_POSE RMSE vs GROUND_TRUTH: {:.1f} mm, heading {:.2f} mrad, over {} fixes\n",
                     report["laser_pose_rmse_mm"].get<double>(),
                     report.value("laser_pose_heading_rmse_mrad", 0.0),
                     report["laser_pose_samples"].get<size_t>());
  out += format_nees("POSE", report["pose_nees"]);
  out += format_nees("LASER_POSE", report["laser_pose_nees"]);
  if (!report["range_bias_mm"].is_null() && !report["range_bias_sigma_mm"].is_null())
    out += fmt::format("pose_solver range bias estimate: {:+.1f} mm (sigma {:.1f} mm)\n",
                       report["range_bias_mm"].get<double>(), report["range_bias_sigma_mm"].get<double>());
  out += fmt::format("odometry-only drift over the run: {:.1f} mm{}\n",
                     report["odometry_drift_mm"].get<double>(),
                     report["odometry_restarts"].get<int>() > 0 ? " (since the last odometry restart)" : "");
  if (report["aborted"].get<bool>())
    out += fmt::format("ABORTED: {}\n", report["abort_reason"].get<std::string>());
  return out;
}

std::string write_mission_results(const MissionMonitor& monitor, const MissionFiles& files) {
  const nlohmann::json report = monitor.report(files.log_file);
  std::string out = format_mission_summary(report);
  if (!files.json_file.empty()) {
    std::ofstream json(files.json_file);
    if (!(json << report.dump(2) << "\n")) throw ConfigError(files.json_file + ": cannot write");
  }
  const std::string trace = !files.trace_file.empty() ? files.trace_file
                            : files.log_file.empty()  ? ""
                                                      : files.log_file + ".trace.csv";
  if (trace.empty()) return out;
  // The summary is the run's result: a trace that cannot be written does not hide it.
  if (!write_path_trace_csv(trace, monitor.path_trace()))
    return out + fmt::format("path trace NOT written: {}: cannot write\n", trace);
  return out + fmt::format("path trace (tools/refloc-plot/refloc-plot.py mission draws it): {}\n", trace);
}

}  // namespace refloc
