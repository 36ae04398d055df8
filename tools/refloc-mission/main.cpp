// refloc-mission: send a mission (NAV_GOAL) to the running stack, watch it,
// and report what a user needs to trust it: the true arrival error at each
// waypoint (from GROUND_TRUTH), the localization RMSE of POSE and LASER_POSE,
// and the odometry-only drift over the run. Writes JSON and an SVG path plot.

#include "common/clock.hpp"
#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/service_runtime.hpp"
#include "mission_progress.hpp"
#include "path_plot_svg.hpp"
#include "trajectory.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace refloc {
namespace {

struct Mission {
  std::vector<Pose2> waypoints;
  double xy_tolerance_m = 0.010;
  double heading_tolerance_rad = 0.5 * M_PI / 180.0;
  double max_speed_m_s = 1.0;
  double timeout_s = 300.0;
  double localization_timeout_s = 60.0;
};

Mission load_mission(const std::string& path) {
  const JsonConfig c = JsonConfig::load_file(path);
  Mission m;
  const size_t n = c.array_size("/waypoints");
  if (n == 0) c.fail("/waypoints", "expected at least one waypoint");
  for (size_t i = 0; i < n; ++i) {
    const std::string w = fmt::format("/waypoints/{}", i);
    m.waypoints.push_back({c.required_number(w + "/x_m", -1e4, 1e4), c.required_number(w + "/y_m", -1e4, 1e4),
                           c.number(w + "/theta_deg", 0.0, -360.0, 360.0) * M_PI / 180.0});
  }
  m.xy_tolerance_m = c.number("/xy_tolerance_m", m.xy_tolerance_m, 0.001, 1.0);
  m.heading_tolerance_rad = c.number("/heading_tolerance_deg", 0.5, 0.01, 45.0) * M_PI / 180.0;
  m.max_speed_m_s = c.number("/max_speed_m_s", m.max_speed_m_s, 0.01, 3.0);
  m.timeout_s = c.number("/timeout_s", m.timeout_s, 1.0, 36000.0);
  m.localization_timeout_s = c.number("/localization_timeout_s", m.localization_timeout_s, 1.0, 3600.0);
  c.reject_unknown_keys();
  return m;
}

Pose2 to_pose(const pose2d_t& m) { return {m.x, m.y, m.theta}; }

struct WaypointResult {
  Pose2 target;
  bool reached = false;
  double error_xy_m = NAN;
  double error_heading_rad = NAN;
};

class MissionMonitor {
 public:
  MissionMonitor(ServiceRuntime& rt, Mission mission)
      : rt_(rt), mission_(std::move(mission)), progress_(mission_.waypoints.size()) {
    results_.resize(mission_.waypoints.size());
    for (size_t i = 0; i < results_.size(); ++i) results_[i].target = mission_.waypoints[i];
    rt_.subscribe<pose2d_t>("GROUND_TRUTH", [this](const pose2d_t& m) {
      truth_.add(m.utime, to_pose(m));
      latest_truth_ = to_pose(m);
      has_truth_ = true;
    });
    rt_.subscribe<pose2d_t>("POSE", [this](const pose2d_t& m) {
      if (m.status == pose2d_t::STATUS_OK) localized_ = true;
      if (driving_ && m.status == pose2d_t::STATUS_OK) pose_.add(m.utime, to_pose(m));
    });
    rt_.subscribe<pose2d_t>("LASER_POSE", [this](const pose2d_t& m) {
      if (driving_ && m.status == pose2d_t::STATUS_OK) laser_pose_.add(m.utime, to_pose(m));
    });
    rt_.subscribe<odometry_t>("ODOMETRY", [this](const odometry_t& m) {
      // A restarted odometry service starts a new frame: drift is measured over the latest one.
      if (m.distance < last_odometry_distance_) {
        odometry_ = Trajectory{};
        ++odometry_restarts_;
      }
      last_odometry_distance_ = m.distance;
      if (driving_) odometry_.add(m.utime, {m.x, m.y, m.theta});
    });
    rt_.subscribe<nav_status_t>("NAV_STATUS", [this](const nav_status_t& m) { on_status(m); });
  }

  int run() {
    const int64_t start = monotonic_us();
    fmt::print("waiting for POSE with status OK ...\n");
    while (!localized_ && !rt_.stop_requested()) {
      if (monotonic_us() - start > static_cast<int64_t>(mission_.localization_timeout_s * 1e6)) {
        fmt::print(stderr, "refloc-mission: no POSE with status OK within {:.0f} s\n",
                   mission_.localization_timeout_s);
        return 1;
      }
      rt_.spin_once(50);
    }
    driving_ = true;
    drive_start_utime_ = now_utime();
    fmt::print("localized; sending a mission with {} waypoints\n", mission_.waypoints.size());
    const int64_t drive_start = monotonic_us();
    while (!progress_.finished() && !rt_.stop_requested()) {
      // Resend until the navigator acknowledges (UDP has no last value for late
      // joiners), and the remaining waypoints whenever a restarted navigator forgot them.
      if (progress_.needs_send(monotonic_us())) send_goal();
      if (monotonic_us() - drive_start > static_cast<int64_t>(mission_.timeout_s * 1e6)) {
        abort_reason_ = fmt::format("timeout after {:.0f} s", mission_.timeout_s);
        break;
      }
      rt_.spin_once(20);
    }
    driving_ = false;
    drive_end_utime_ = now_utime();
    return 0;
  }

  nlohmann::json report(const std::string& log_file) const {
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
    j["pose_samples"] = pose_stats.count;
    j["laser_pose_rmse_mm"] = laser_stats.rmse_xy_m * 1000.0;
    j["laser_pose_samples"] = laser_stats.count;
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

  std::vector<PlotSeries> plot_series() const {
    auto points = [](const Trajectory& t) {
      std::vector<Eigen::Vector2d> p;
      for (const auto& s : t.samples()) p.push_back(s.pose.translation());
      return p;
    };
    std::vector<Eigen::Vector2d> targets;
    for (const auto& w : mission_.waypoints) targets.push_back(w.translation());
    return {{"ground truth", "black", points(truth_), false},
            {"POSE (fused)", "#1f77b4", points(pose_), false},
            {"LASER_POSE", "#ff7f0e", points(laser_pose_), true},
            {"waypoints", "#d62728", targets, true}};
  }

  bool all_reached() const {
    return std::all_of(results_.begin(), results_.end(), [](const auto& r) { return r.reached; });
  }

 private:
  void send_goal() {
    const bool resend = progress_.goal_id() != 0;
    nav_goal_t goal;
    goal.utime = now_utime();
    goal.goal_id = progress_.start_goal(goal.utime, monotonic_us());
    goal.xy_tolerance = mission_.xy_tolerance_m;
    goal.heading_tolerance = mission_.heading_tolerance_rad;
    goal.max_speed = mission_.max_speed_m_s;
    for (size_t i = progress_.first_waypoint(); i < mission_.waypoints.size(); ++i) {
      const Pose2& w = mission_.waypoints[i];
      goal.x.push_back(w.x);
      goal.y.push_back(w.y);
      goal.theta.push_back(w.theta);
    }
    goal.nwaypoints = static_cast<int32_t>(goal.x.size());
    rt_.publish("NAV_GOAL", goal);
    if (resend) {
      fmt::print("resending waypoints {}..{} as goal {} (navigator restarted or silent)\n",
                 progress_.first_waypoint(), mission_.waypoints.size() - 1, goal.goal_id);
      ++rt_.counter("goal_resends");
    } else {
      fmt::print("sent mission {}\n", goal.goal_id);
    }
  }

  void on_status(const nav_status_t& m) {
    if (!driving_) return;
    const int64_t now = monotonic_us();
    const size_t newly =
        progress_.on_status(m.goal_id, static_cast<NavStatusState>(m.state), m.waypoints_reached, now);
    for (size_t i = progress_.reached() - newly; i < progress_.reached(); ++i) {
      auto& r = results_[i];
      r.reached = true;
      if (has_truth_) {
        r.error_xy_m = std::hypot(latest_truth_.x - r.target.x, latest_truth_.y - r.target.y);
        r.error_heading_rad = angle_diff(latest_truth_.theta, r.target.theta);
      }
      fmt::print("waypoint {} reached: true error {:.1f} mm, {:.2f} deg\n", i, r.error_xy_m * 1000.0,
                 r.error_heading_rad * 180.0 / M_PI);
    }
    if (progress_.aborted() && abort_reason_.empty()) abort_reason_ = "navigator aborted: " + m.reason;
  }

  /// Odometry alone, anchored to the truth at the first odometry sample of the run.
  double odometry_drift_m() const {
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

  ServiceRuntime& rt_;
  Mission mission_;
  std::vector<WaypointResult> results_;
  Trajectory truth_, pose_, laser_pose_, odometry_;
  Pose2 latest_truth_;
  bool has_truth_ = false;
  bool localized_ = false;
  bool driving_ = false;
  MissionProgress progress_;
  double last_odometry_distance_ = 0.0;
  int odometry_restarts_ = 0;
  int64_t drive_start_utime_ = 0;
  int64_t drive_end_utime_ = 0;
  std::string abort_reason_;
};

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Send a mission to the running refloc stack and report arrival and localization errors"};
  std::string mission_file = "deploy/config/mission_demo.json", lcm_url, json_file, log_file, plot_file;
  app.add_option("--mission", mission_file, "mission file (JSON waypoints)")->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_option("--json", json_file, "write the results as JSON to this file");
  app.add_option("--log-file", log_file, "the LCM log recorded alongside (reported in the JSON)");
  app.add_option("--plot", plot_file, "SVG plot of true vs estimated path (default: <log-file>.svg)");
  CLI11_PARSE(app, argc, argv);
  // Progress lines as they happen, also into a pipe or file a supervising script reads.
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  return refloc::guarded_main("refloc-mission", [&] {
    refloc::setup_logging("refloc-mission");
    const refloc::Mission mission = refloc::load_mission(mission_file);
    refloc::ServiceRuntime runtime("refloc-mission", lcm_url);
    refloc::MissionMonitor monitor(runtime, mission);
    if (monitor.run() != 0) return 1;
    const nlohmann::json report = monitor.report(log_file);
    fmt::print("\nwaypoints reached: {}/{}\n", report["waypoints_reached"].get<size_t>(),
               report["waypoints_total"].get<size_t>());
    fmt::print("max true waypoint error: {:.1f} mm, {:.2f} deg\n",
               report["max_waypoint_error_mm"].get<double>(),
               report["max_waypoint_heading_error_deg"].get<double>());
    fmt::print("POSE RMSE vs GROUND_TRUTH: {:.1f} mm over {} samples\n", report["pose_rmse_mm"].get<double>(),
               report["pose_samples"].get<size_t>());
    fmt::print("LASER_POSE RMSE vs GROUND_TRUTH: {:.1f} mm over {} fixes\n",
               report["laser_pose_rmse_mm"].get<double>(), report["laser_pose_samples"].get<size_t>());
    fmt::print("odometry-only drift over the run: {:.1f} mm{}\n", report["odometry_drift_mm"].get<double>(),
               report["odometry_restarts"].get<int>() > 0 ? " (since the last odometry restart)" : "");
    if (report["aborted"].get<bool>()) fmt::print("ABORTED: {}\n", report["abort_reason"].get<std::string>());
    if (!json_file.empty()) std::ofstream(json_file) << report.dump(2) << "\n";
    if (plot_file.empty() && !log_file.empty()) plot_file = log_file + ".svg";
    if (!plot_file.empty()) {
      refloc::write_path_plot_svg(plot_file, "refloc mission: true vs estimated path", monitor.plot_series());
      fmt::print("path plot: {}\n", plot_file);
    }
    return monitor.all_reached() ? 0 : 1;
  });
}
