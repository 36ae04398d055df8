#include "navigator/navigator_node.hpp"

#include <fmt/format.h>

namespace refloc {
namespace {

bool goal_active(NavState s) { return s == NavState::kDriving || s == NavState::kStoppedNoPose; }

}  // namespace

NavigatorNode::NavigatorNode(const NavigatorConfig& config) : navigator_(config) {}

const NavStatus* NavigatorNode::status_to_publish(bool only_on_change) {
  const NavStatus& s = navigator_.status();
  const bool changed = !published_once_ || s.state != published_.state || s.goal_id != published_.goal_id ||
                       s.waypoints_reached != published_.waypoints_reached || s.reason != published_.reason;
  if (only_on_change && !changed) return nullptr;
  if (changed) {
    events_.push_back(
        {nullptr, NodeEvent::Level::kInfo,
         fmt::format("goal {}: {} (waypoint {}/{}){}{}", s.goal_id, to_string(s.state), s.waypoints_reached,
                     s.nwaypoints, s.reason.empty() ? "" : ": ", s.reason)});
  }
  published_ = s;
  published_once_ = true;
  return &navigator_.status();
}

NavigatorOutput NavigatorNode::on_goal(const NavGoal& goal, int64_t now_utime) {
  events_.clear();
  if (!navigator_.set_goal(goal, now_utime)) return {};  // republished, already running
  if (navigator_.status().state == NavState::kAborted) events_.push_back(counted("goals_refused"));
  return {std::nullopt, status_to_publish(true)};
}

void NavigatorNode::on_pose(const Pose2& map_T_robot, int64_t pose_utime, PoseQuality quality) {
  navigator_.set_pose(map_T_robot, pose_utime, quality);
}

NavigatorOutput NavigatorNode::on_control_tick(int64_t now_utime) {
  events_.clear();
  const NavState before = navigator_.status().state;
  const BodyTwist cmd = navigator_.update(now_utime);
  const NavState after = navigator_.status().state;
  if (after == NavState::kStoppedNoPose && before != NavState::kStoppedNoPose) {
    events_.push_back(counted("pose_stops"));
  }
  if (goal_active(before) || goal_active(after)) last_active_utime_ = now_utime;
  NavigatorOutput out;
  // Fall silent a while after a goal ends so another commander (teleoperation) may drive.
  if (now_utime - last_active_utime_ <= kCommandHoldUs) out.command = cmd;
  out.status = status_to_publish(true);
  return out;
}

NavigatorOutput NavigatorNode::on_status_tick() {
  events_.clear();
  return {std::nullopt, status_to_publish(false)};
}

NavigatorHealth NavigatorNode::health() const {
  const NavStatus& s = navigator_.status();
  if (s.state == NavState::kStoppedNoPose) return {false, s.reason};
  return {true, ""};
}

}  // namespace refloc
