// refloc-mission: send a mission (NAV_GOAL) to the running stack, report true waypoint errors,
// POSE/LASER_POSE RMSE and NEES, odometry drift and pose_solver's range bias. MissionMonitor
// records and decides; this converts LCM.

#include "common/clock.hpp"
#include "common/guarded_main.hpp"
#include "common/lcm_conversions.hpp"
#include "common/program_version.hpp"
#include "common/service_runtime.hpp"
#include "heartbeat_from_lcm.hpp"
#include "mission_monitor.hpp"
#include "mission_summary.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <cstdio>
#include <tuple>

namespace refloc {
namespace {

Pose2 to_pose(const pose2d_t& m) { return {m.x, m.y, m.theta}; }

nav_goal_t to_lcm(const GoalRequest& g) {
  nav_goal_t goal{};
  goal.utime = g.utime;
  goal.goal_id = g.goal_id;
  goal.nwaypoints = static_cast<int32_t>(g.x_m.size());
  std::tie(goal.x, goal.y, goal.theta) = std::tie(g.x_m, g.y_m, g.theta_rad);
  goal.xy_tolerance = g.xy_tolerance_m;
  goal.heading_tolerance = g.heading_tolerance_rad;
  goal.max_speed = g.max_speed_m_s;
  return goal;
}

void subscribe(ServiceRuntime& rt, MissionMonitor& m) {
  const auto ok = [](const pose2d_t& p) { return p.status == pose2d_t::STATUS_OK; };
  rt.subscribe<pose2d_t>("GROUND_TRUTH", [&m](const pose2d_t& p) { m.on_ground_truth(p.utime, to_pose(p)); });
  rt.subscribe<pose2d_t>("POSE", [&m, ok](const pose2d_t& p) {
    m.on_pose(p.utime, to_pose(p), ok(p), covariance_from_lcm(p.covariance));
  });
  rt.subscribe<pose2d_t>("LASER_POSE", [&m, ok](const pose2d_t& p) {
    m.on_laser_pose(p.utime, to_pose(p), ok(p), covariance_from_lcm(p.covariance));
  });
  rt.subscribe<heartbeat_t>("HEARTBEAT",
                            [&m](const heartbeat_t& h) { m.on_heartbeat(heartbeat_from_lcm(h)); });
  rt.subscribe<odometry_t>("ODOMETRY", [&m](const odometry_t& o) {
    m.on_odometry(o.utime, {o.x, o.y, o.theta}, o.distance);
  });
  rt.subscribe<nav_status_t>("NAV_STATUS", [&m](const nav_status_t& s) {
    const auto state = static_cast<NavStatusState>(s.state);
    for (size_t i : m.on_status(s.goal_id, state, s.waypoints_reached, s.reason, monotonic_us()))
      fmt::print("{}", format_waypoint_reached(i, m.result(i)));
  });
}

/// Waits for a POSE with status OK, drives until finished, aborted or timed out; 1: never localized.
int drive(ServiceRuntime& rt, MissionMonitor& m) {
  fmt::print("waiting for POSE with status OK ...\n");
  for (m.start_waiting(monotonic_us()); !m.localized() && !rt.stop_requested(); rt.spin_once(50)) {
    if (!m.localization_timed_out(monotonic_us())) continue;
    fmt::print(stderr, "refloc-mission: no POSE with status OK within {:.0f} s\n",
               m.mission().localization_timeout_s);
    return 1;
  }
  m.start_driving(now_utime(), monotonic_us());
  fmt::print("localized; sending a mission with {} waypoints\n", m.mission().waypoints.size());
  for (; m.driving() && !rt.stop_requested() && !m.timed_out(monotonic_us()); rt.spin_once(20)) {
    const auto goal = m.goal_due(now_utime(), monotonic_us());
    if (!goal) continue;
    rt.publish("NAV_GOAL", to_lcm(*goal));
    if (goal->resend) ++rt.counter("goal_resends");
    fmt::print("{}", format_goal_sent(*goal, m.mission().waypoints.size()));
  }
  m.stop_driving(now_utime());
  return 0;
}

int run(const MissionFiles& files, const std::string& mission_file, const std::string& lcm_url) {
  setup_logging("refloc-mission");
  MissionMonitor monitor(load_mission(mission_file));
  ServiceRuntime runtime("refloc-mission", lcm_url);
  subscribe(runtime, monitor);
  if (drive(runtime, monitor) != 0) return 1;
  fmt::print("{}", write_mission_results(monitor, files));
  return monitor.all_reached() ? 0 : 1;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Send a mission to the running refloc stack and report arrival and localization errors"};
  refloc::add_version_flag(app, "refloc-mission");
  std::string mission_file = refloc::shipped_path("deploy/config/mission_demo.json"), lcm_url;
  refloc::MissionFiles f;
  app.add_option("--mission", mission_file, "mission file (JSON waypoints)")->capture_default_str();
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_option("--json", f.json_file, "write the results as JSON to this file");
  app.add_option("--log-file", f.log_file, "the LCM log recorded alongside (reported in the JSON)");
  app.add_option("--trace", f.trace_file,
                 "CSV of the paths and errors for tools/refloc-plot (default: <log-file>.trace.csv)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines as they happen, also into a pipe
  return refloc::guarded_main("refloc-mission", [&] { return refloc::run(f, mission_file, lcm_url); });
}
