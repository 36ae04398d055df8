#include "navigator/navigator_node.hpp"

#include "navigator/navigator_input_checks.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {
namespace {

bool goal_active(NavState s) { return s == NavState::kDriving || s == NavState::kStoppedNoPose; }

const char* goal_counter(NavInputProblem p) {
  return p == NavInputProblem::kNonFinite ? "rejected_nav_goal_nonfinite" : "rejected_nav_goal_out_of_bounds";
}

const char* pose_counter(NavInputProblem p) {
  return p == NavInputProblem::kNonFinite ? "rejected_pose_nonfinite" : "rejected_pose_out_of_bounds";
}

const char* pose_stamp_counter(StampVerdict v) {
  switch (v) {
    case StampVerdict::kAhead:
      return "rejected_pose_stamp_ahead";
    case StampVerdict::kBehind:
      return "rejected_pose_stamp_behind";
    case StampVerdict::kNotIncreasing:
      return "rejected_pose_stamp_not_increasing";
    case StampVerdict::kReanchored:
      return "reanchored_pose";
    case StampVerdict::kAccepted:
      break;
  }
  return nullptr;
}

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
  // A goal with broken numbers must not end the goal being driven: a buggy or hostile sender
  // (even one reusing the active goal's id) would otherwise stop every mission. While a goal is
  // active it is refused on the side, counted and logged; with nothing active it is ABORTED with
  // its reason in NAV_STATUS, so its sender hears why.
  if (!goal.waypoints.empty() && goal_active(navigator_.status().state)) {
    const GoalCheck check = check_goal(goal);
    if (check.problem != NavInputProblem::kNone) {
      events_.push_back(counted("goals_refused"));
      events_.push_back({goal_counter(check.problem), NodeEvent::Level::kWarn,
                         fmt::format("NAV_GOAL {} refused, goal {} goes on: {}", goal.goal_id,
                                     navigator_.status().goal_id, check.reason)});
      return {};
    }
  }
  if (!navigator_.set_goal(goal, now_utime)) return {};  // republished, already running
  if (navigator_.status().state == NavState::kAborted) {
    events_.push_back(counted("goals_refused"));
    const GoalCheck check = check_goal(goal);
    if (check.problem != NavInputProblem::kNone) events_.push_back(counted(goal_counter(check.problem)));
  }
  return {std::nullopt, status_to_publish(true)};
}

void NavigatorNode::on_pose(const Pose2& map_T_robot, int64_t pose_utime, PoseQuality quality,
                            int64_t host_utime) {
  events_.clear();
  const NavInputProblem problem = check_pose(map_T_robot);
  if (problem != NavInputProblem::kNone) {
    events_.push_back({pose_counter(problem), NodeEvent::Level::kWarn,
                       fmt::format("POSE at utime {} refused: {} pose", pose_utime, to_string(problem))});
    return;
  }
  const StampVerdict verdict = pose_stamps_.check(pose_utime, host_utime);
  if (!stamp_accepted(verdict)) {
    events_.push_back({pose_stamp_counter(verdict), NodeEvent::Level::kWarn,
                       fmt::format("POSE at utime {} refused: stamp {}", pose_utime, to_string(verdict))});
    return;
  }
  if (verdict == StampVerdict::kReanchored) {
    events_.push_back({pose_stamp_counter(verdict), NodeEvent::Level::kWarn,
                       "POSE clock stepped: the stream's stamps are believed from here"});
  }
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
  if (now_utime - last_active_utime_ <= kCommandHoldUs) {
    const NavigatorConfig& c = navigator_.config();
    bool changed = false;
    out.command = bounded_command(cmd, c.translation.max_speed, c.rotation.max_speed, changed);
    if (changed) {
      const bool finite = std::isfinite(cmd.vx) && std::isfinite(cmd.vy) && std::isfinite(cmd.wz);
      events_.push_back({finite ? "commands_clamped" : "commands_nonfinite_zeroed", NodeEvent::Level::kWarn,
                         fmt::format("CMD_VEL ({}, {}, {}) {}", cmd.vx, cmd.vy, cmd.wz,
                                     finite ? "above the limits: clamped" : "not finite: zero instead")});
    }
  }
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
