// navigator: NAV_GOAL (nav_goal_t) + POSE (pose2d_t) -> CMD_VEL (twist_t) at the
// control rate while a goal is active, NAV_STATUS (nav_status_t) on every change
// and at the status rate. Every decision is NavigatorNode's.

#include "common/clock.hpp"
#include "common/node_event_report.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "navigator/navigator_config_file.hpp"
#include "navigator/navigator_node.hpp"

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

twist_t to_message(const BodyTwist& cmd, int64_t utime) {
  twist_t msg{};
  msg.utime = utime;
  msg.vx = cmd.vx;
  msg.vy = cmd.vy;
  msg.wz = cmd.wz;
  return msg;
}

int run(const std::string& lcm_url, const std::string& config_path) {
  const NavigatorServiceConfig config = load_navigator_service_config(config_path);
  ServiceRuntime runtime("navigator", lcm_url);
  NavigatorNode node(config.navigator);
  const auto publish = [&](const NavigatorOutput& out, int64_t now) {
    report_events(runtime, node.events());
    if (out.command) runtime.publish(config.command_channel, to_message(*out.command, now));
    if (out.status) runtime.publish(config.status_channel, to_message(*out.status, now_utime()));
  };
  runtime.subscribe<nav_goal_t>(config.goal_channel, [&](const nav_goal_t& msg) {
    const int64_t now = now_utime();
    publish(node.on_goal(to_goal(msg), now), now);
  });
  runtime.subscribe<pose2d_t>(config.pose_channel, [&](const pose2d_t& msg) {
    node.on_pose({msg.x, msg.y, msg.theta}, msg.utime, to_quality(msg.status), now_utime());
    report_events(runtime, node.events());
  });
  runtime.add_periodic(1.0 / config.control_rate, [&] {
    const int64_t now = now_utime();
    publish(node.on_control_tick(now), now);
    const NavigatorHealth health = node.health();
    runtime.set_state(health.ok ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED, health.detail);
  });
  runtime.add_periodic(1.0 / config.status_rate, [&] { publish(node.on_status_tick(), now_utime()); });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("navigator",
                                 "Holonomic waypoint navigator: NAV_GOAL + POSE -> CMD_VEL, NAV_STATUS", "");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_navigator_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path); });
}
