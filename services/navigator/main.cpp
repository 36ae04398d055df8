// navigator: NAV_GOAL (nav_goal_t) + POSE (pose2d_t) -> CMD_VEL (twist_t) at the
// control rate while a goal is active, NAV_STATUS (nav_status_t) on every change
// and at the status rate.

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "navigator/navigator.hpp"
#include "navigator/navigator_config_file.hpp"

#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/twist_t.hpp>

namespace refloc {
namespace {

NavGoal to_goal(const nav_goal_t& msg) {
  NavGoal goal;
  goal.goal_id = msg.goal_id;
  goal.xy_tolerance = msg.xy_tolerance;
  goal.heading_tolerance = msg.heading_tolerance;
  goal.max_speed = msg.max_speed;
  const size_t n = std::min(
      {static_cast<size_t>(std::max(msg.nwaypoints, 0)), msg.x.size(), msg.y.size(), msg.theta.size()});
  for (size_t i = 0; i < n; ++i) goal.waypoints.push_back({msg.x[i], msg.y[i], msg.theta[i]});
  return goal;
}

nav_status_t to_message(const NavStatus& s, int64_t utime) {
  nav_status_t msg{};
  msg.utime = utime;
  msg.goal_id = s.goal_id;
  msg.state = static_cast<int8_t>(s.state);
  msg.waypoint_index = s.waypoint_index;
  msg.waypoints_reached = s.waypoints_reached;
  msg.nwaypoints = s.nwaypoints;
  msg.distance_to_waypoint = s.distance_to_waypoint;
  msg.heading_error = s.heading_error;
  msg.reason = s.reason;
  return msg;
}

PoseQuality to_quality(int8_t status) {
  if (status == pose2d_t::STATUS_OK) return PoseQuality::kGood;
  if (status == pose2d_t::STATUS_DEGRADED) return PoseQuality::kDegraded;
  return PoseQuality::kUnusable;
}

bool goal_active(NavState s) { return s == NavState::kDriving || s == NavState::kStoppedNoPose; }

int run(const std::string& lcm_url, const std::string& config_path) {
  NavigatorServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_navigator_service_config(file);
    file.reject_unknown_keys();
  }
  ServiceRuntime runtime("navigator", lcm_url);
  Navigator navigator(config.navigator);
  NavStatus published;
  bool published_once = false;
  int64_t last_active_utime = 0;

  const auto publish_status = [&](bool only_on_change) {
    const NavStatus& s = navigator.status();
    const bool changed = !published_once || s.state != published.state || s.goal_id != published.goal_id ||
                         s.waypoints_reached != published.waypoints_reached || s.reason != published.reason;
    if (only_on_change && !changed) return;
    if (changed) {
      spdlog::info("goal {}: {} (waypoint {}/{}){}{}", s.goal_id, to_string(s.state), s.waypoints_reached,
                   s.nwaypoints, s.reason.empty() ? "" : ": ", s.reason);
    }
    runtime.publish(config.status_channel, to_message(s, now_utime()));
    published = s;
    published_once = true;
  };

  runtime.subscribe<nav_goal_t>(config.goal_channel, [&](const nav_goal_t& msg) {
    if (!navigator.set_goal(to_goal(msg), now_utime())) return;  // republished, already running
    if (navigator.status().state == NavState::kAborted) ++runtime.counter("goals_refused");
    publish_status(true);
  });
  runtime.subscribe<pose2d_t>(config.pose_channel, [&](const pose2d_t& msg) {
    navigator.set_pose({msg.x, msg.y, msg.theta}, msg.utime, to_quality(msg.status));
  });
  runtime.add_periodic(1.0 / config.control_rate, [&] {
    const int64_t now = now_utime();
    const NavState before = navigator.status().state;
    const TwistCommand cmd = navigator.update(now);
    const NavState after = navigator.status().state;
    if (after == NavState::kStoppedNoPose && before != NavState::kStoppedNoPose)
      ++runtime.counter("pose_stops");
    if (goal_active(before) || goal_active(after)) last_active_utime = now;
    // Keep commanding (zeros once done) for half a second after a goal ends, then
    // fall silent so another commander (teleoperation) may drive.
    if (now - last_active_utime <= 500'000) {
      twist_t msg{};
      msg.utime = now;
      msg.vx = cmd.vx;
      msg.vy = cmd.vy;
      msg.wz = cmd.wz;
      runtime.publish(config.command_channel, msg);
    }
    publish_status(true);
    runtime.set_state(after == NavState::kStoppedNoPose ? heartbeat_t::STATE_DEGRADED : heartbeat_t::STATE_OK,
                      after == NavState::kStoppedNoPose ? navigator.status().reason : "");
  });
  runtime.add_periodic(1.0 / config.status_rate, [&] { publish_status(false); });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("navigator",
                                 "Holonomic waypoint navigator: NAV_GOAL + POSE -> CMD_VEL, NAV_STATUS", "");
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path); });
}
