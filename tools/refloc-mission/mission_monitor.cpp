#include "mission_monitor.hpp"

#include "common/angles.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace refloc {
namespace {

/// Metres as millimetres, or null when never heard.
nlohmann::json optional_mm(const std::optional<double>& value_m) {
  return value_m ? nlohmann::json(*value_m * 1000.0) : nlohmann::json(nullptr);
}

}  // namespace

MissionMonitor::MissionMonitor(Mission mission, const MissionProgressConfig& progress)
    : mission_(std::move(mission)), progress_(mission_.waypoints.size(), progress) {
  results_.resize(mission_.waypoints.size());
  for (size_t i = 0; i < results_.size(); ++i) results_[i].target = mission_.waypoints[i];
}

void MissionMonitor::on_ground_truth(int64_t utime, const Pose2& map_T_robot) {
  truth_.add(utime, map_T_robot);
  latest_truth_ = map_T_robot;
  latest_truth_utime_ = utime;
  has_truth_ = true;
}

void MissionMonitor::on_pose(int64_t utime, const Pose2& map_T_robot, bool ok,
                             const Eigen::Matrix3d& covariance) {
  if (ok) localized_ = true;
  if (!driving_ || !ok) return;
  pose_.add(utime, map_T_robot);
  pose_fixes_.push_back({utime, map_T_robot, covariance});
}

void MissionMonitor::on_laser_pose(int64_t utime, const Pose2& map_T_robot, bool ok,
                                   const Eigen::Matrix3d& covariance) {
  if (!driving_ || !ok) return;
  laser_pose_.add(utime, map_T_robot);
  laser_fixes_.push_back({utime, map_T_robot, covariance});
}

void MissionMonitor::on_heartbeat(const HeartbeatSample& heartbeat) {
  if (heartbeat.service != "pose_solver") return;
  for (const auto& [name, value] : heartbeat.counters) {
    if (name == "range_bias_um") range_bias_m_ = static_cast<double>(value) * 1e-6;
    if (name == "range_bias_sigma_um") range_bias_sigma_m_ = static_cast<double>(value) * 1e-6;
  }
}

void MissionMonitor::on_odometry(int64_t utime, const Pose2& odom_T_robot, double distance_m) {
  if (distance_m < last_odometry_distance_m_) {
    odometry_ = Trajectory{};
    ++odometry_restarts_;
  }
  last_odometry_distance_m_ = distance_m;
  if (driving_) odometry_.add(utime, odom_T_robot);
}

std::vector<size_t> MissionMonitor::on_status(int64_t goal_id, NavStatusState state,
                                              int32_t waypoints_reached, const std::string& reason,
                                              int64_t now_us) {
  std::vector<size_t> reached;
  if (!driving_) return reached;
  const size_t newly = progress_.on_status(goal_id, state, waypoints_reached, now_us);
  for (size_t i = progress_.reached() - newly; i < progress_.reached(); ++i) {
    WaypointResult& r = results_[i];
    r.reached = true;
    if (has_truth_) {
      r.error_xy_m = std::hypot(latest_truth_.x - r.target.x, latest_truth_.y - r.target.y);
      r.error_heading_rad = angle_diff(latest_truth_.theta, r.target.theta);
      r.reached_utime = latest_truth_utime_;
    }
    reached.push_back(i);
  }
  if (progress_.aborted() && abort_reason_.empty()) abort_reason_ = "navigator aborted: " + reason;
  return reached;
}

void MissionMonitor::start_driving(int64_t utime, int64_t now_us) {
  driving_ = true;
  drive_start_utime_ = utime;
  drive_start_us_ = now_us;
}

std::optional<GoalRequest> MissionMonitor::goal_due(int64_t utime, int64_t now_us) {
  if (!progress_.needs_send(now_us)) return std::nullopt;
  GoalRequest g;
  g.utime = utime;
  g.resend = progress_.goal_id() != 0;
  g.goal_id = progress_.start_goal(utime, now_us);
  g.first_waypoint = progress_.first_waypoint();
  for (size_t i = g.first_waypoint; i < mission_.waypoints.size(); ++i) {
    g.x_m.push_back(mission_.waypoints[i].x);
    g.y_m.push_back(mission_.waypoints[i].y);
    g.theta_rad.push_back(mission_.waypoints[i].theta);
  }
  g.xy_tolerance_m = mission_.xy_tolerance_m;
  g.heading_tolerance_rad = mission_.heading_tolerance_rad;
  g.max_speed_m_s = mission_.max_speed_m_s;
  return g;
}

bool MissionMonitor::timed_out(int64_t now_us) {
  if (now_us - drive_start_us_ <= static_cast<int64_t>(mission_.timeout_s * 1e6)) return false;
  if (abort_reason_.empty()) abort_reason_ = fmt::format("timeout after {:.0f} s", mission_.timeout_s);
  return true;
}

void MissionMonitor::stop_driving(int64_t utime) {
  driving_ = false;
  drive_end_utime_ = utime;
}

bool MissionMonitor::all_reached() const {
  return std::all_of(results_.begin(), results_.end(), [](const auto& r) { return r.reached; });
}

nlohmann::json MissionMonitor::report(const std::string& log_file) const {
  nlohmann::json j;
  size_t reached = 0;
  double max_xy = 0.0, max_heading = 0.0;
  nlohmann::json waypoints = nlohmann::json::array();
  for (size_t i = 0; i < results_.size(); ++i) {
    const auto& r = results_[i];
    nlohmann::json w = {{"index", i},
                        {"x_m", r.target.x},
                        {"y_m", r.target.y},
                        {"theta_deg", r.target.theta * 180.0 / M_PI},
                        {"reached", r.reached}};
    if (r.reached) {
      ++reached;
      max_xy = std::max(max_xy, r.error_xy_m);
      max_heading = std::max(max_heading, std::abs(r.error_heading_rad));
      w["error_mm"] = r.error_xy_m * 1000.0;
      w["heading_error_deg"] = r.error_heading_rad * 180.0 / M_PI;
    }
    waypoints.push_back(w);
  }
  const ErrorStats pose_stats = compare(pose_, truth_, drive_start_utime_);
  const ErrorStats laser_stats = compare(laser_pose_, truth_, drive_start_utime_);
  j["waypoints_total"] = results_.size();
  j["waypoints_reached"] = reached;
  j["max_waypoint_error_mm"] = max_xy * 1000.0;
  j["max_waypoint_heading_error_deg"] = max_heading * 180.0 / M_PI;
  j["pose_rmse_mm"] = pose_stats.rmse_xy_m * 1000.0;
  j["pose_max_error_mm"] = pose_stats.max_xy_m * 1000.0;
  j["pose_max_error_moving_mm"] = pose_stats.max_xy_moving_m * 1000.0;
  j["pose_samples"] = pose_stats.count;
  j["pose_heading_rmse_mrad"] = pose_stats.rmse_heading_rad * 1000.0;
  j["laser_pose_rmse_mm"] = laser_stats.rmse_xy_m * 1000.0;
  j["laser_pose_heading_rmse_mrad"] = laser_stats.rmse_heading_rad * 1000.0;
  j["laser_pose_samples"] = laser_stats.count;
  j["pose_nees"] = consistency_json(consistency_against_truth(pose_fixes_, truth_, drive_start_utime_));
  j["laser_pose_nees"] =
      consistency_json(consistency_against_truth(laser_fixes_, truth_, drive_start_utime_));
  j["range_bias_mm"] = optional_mm(range_bias_m_);
  j["range_bias_sigma_mm"] = optional_mm(range_bias_sigma_m_);
  j["odometry_drift_mm"] = odometry_drift_m() * 1000.0;
  j["duration_s"] = static_cast<double>(drive_end_utime_ - drive_start_utime_) * 1e-6;
  j["odometry_restarts"] = odometry_restarts_;
  j["goal_resends"] = progress_.resends();
  j["navigator_goal_losses"] = progress_.goals_lost();
  j["aborted"] = !abort_reason_.empty();
  j["abort_reason"] = abort_reason_;
  j["log_file"] = log_file;
  j["waypoints"] = waypoints;
  return j;
}

PathTrace MissionMonitor::path_trace() const {
  PathTrace trace;
  trace.start_utime = drive_start_utime_;
  for (const auto& s : truth_.samples()) {
    if (s.utime >= drive_start_utime_ && (driving_ || s.utime <= drive_end_utime_))
      trace.samples.push_back({"GROUND_TRUTH", s.utime, s.pose, NAN});
  }
  // The error at a stamp the way compare() takes it for the RMSE.
  for (const auto& [channel, estimate] : {std::pair{"POSE", &pose_}, std::pair{"LASER_POSE", &laser_pose_}}) {
    for (const auto& s : estimate->samples()) {
      if (s.utime < drive_start_utime_) continue;
      const auto truth = truth_.at(s.utime);
      const double error_m = truth ? std::hypot(s.pose.x - truth->x, s.pose.y - truth->y) : NAN;
      trace.samples.push_back({channel, s.utime, s.pose, error_m});
    }
  }
  for (const auto& r : results_)
    trace.waypoints.push_back({r.target, r.reached, r.reached_utime, r.error_xy_m});
  return trace;
}

double MissionMonitor::odometry_drift_m() const {
  if (odometry_.samples().size() < 2) return NAN;
  const auto& first = odometry_.samples().front();
  const auto& last = odometry_.samples().back();
  const auto truth_first = truth_.at(first.utime);
  const auto truth_last = truth_.at(last.utime);
  if (!truth_first || !truth_last) return NAN;
  const Pose2 map_T_odom = *truth_first * first.pose.inverse();
  const Pose2 estimate = map_T_odom * last.pose;
  return std::hypot(estimate.x - truth_last->x, estimate.y - truth_last->y);
}

}  // namespace refloc
