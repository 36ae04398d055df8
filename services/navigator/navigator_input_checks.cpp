#include "navigator/navigator_input_checks.hpp"

#include "common/input_sanity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

const char* to_string(NavInputProblem problem) {
  switch (problem) {
    case NavInputProblem::kNone:
      return "none";
    case NavInputProblem::kNonFinite:
      return "nonfinite";
    case NavInputProblem::kOutOfBounds:
      return "out_of_bounds";
  }
  return "unknown";
}

GoalCheck check_goal(const NavGoal& goal) {
  for (size_t i = 0; i < goal.waypoints.size(); ++i) {
    const Waypoint& w = goal.waypoints[i];
    if (!all_finite({w.x, w.y, w.theta}))
      return {NavInputProblem::kNonFinite, fmt::format("invalid goal: waypoint {} is not finite", i)};
    if (!finite_abs_at_most(w.x, kMaxAbsWaypoint_m) || !finite_abs_at_most(w.y, kMaxAbsWaypoint_m) ||
        !finite_abs_at_most(w.theta, kMaxAbsHeading_rad)) {
      return {NavInputProblem::kOutOfBounds, fmt::format("invalid goal: waypoint {} beyond {} m or {} rad", i,
                                                         kMaxAbsWaypoint_m, kMaxAbsHeading_rad)};
    }
  }
  if (!all_finite({goal.xy_tolerance, goal.heading_tolerance, goal.max_speed}))
    return {NavInputProblem::kNonFinite, "invalid goal: tolerance or speed is not finite"};
  if (!(goal.xy_tolerance <= kMaxXyTolerance_m) || !(goal.heading_tolerance <= kMaxHeadingTolerance_rad) ||
      !(goal.max_speed <= kMaxGoalSpeed_m_s)) {
    return {NavInputProblem::kOutOfBounds,
            fmt::format("invalid goal: tolerance above {} m / {} rad or speed above {} m/s",
                        kMaxXyTolerance_m, kMaxHeadingTolerance_rad, kMaxGoalSpeed_m_s)};
  }
  return {};
}

NavInputProblem check_pose(const Pose2& p) {
  if (!all_finite({p.x, p.y, p.theta})) return NavInputProblem::kNonFinite;
  if (!finite_abs_at_most(p.x, kMaxAbsWaypoint_m) || !finite_abs_at_most(p.y, kMaxAbsWaypoint_m) ||
      !finite_abs_at_most(p.theta, kMaxAbsHeading_rad)) {
    return NavInputProblem::kOutOfBounds;
  }
  return NavInputProblem::kNone;
}

BodyTwist bounded_command(const BodyTwist& cmd, double max_speed_m_s, double max_yaw_rate_rad_s,
                          bool& changed) {
  changed = false;
  if (!all_finite({cmd.vx, cmd.vy, cmd.wz})) {
    changed = true;
    return {};
  }
  BodyTwist out = cmd;
  const double speed = std::hypot(cmd.vx, cmd.vy);
  if (speed > max_speed_m_s) {
    out.vx *= max_speed_m_s / speed;
    out.vy *= max_speed_m_s / speed;
    changed = true;
  }
  if (std::abs(cmd.wz) > max_yaw_rate_rad_s) {
    out.wz = std::clamp(cmd.wz, -max_yaw_rate_rad_s, max_yaw_rate_rad_s);
    changed = true;
  }
  return out;
}

}  // namespace refloc
