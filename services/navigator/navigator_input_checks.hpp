#pragma once
// What the navigator believes of the numbers it consumes and what it lets out.
// NAV_GOAL: waypoints finite and within kMaxAbsWaypoint_m of the map origin, headings
// within kMaxAbsHeading_rad, tolerances and speed finite and at most kMaxXyTolerance_m,
// kMaxHeadingTolerance_rad, kMaxGoalSpeed_m_s (<= 0 still means "the default"); a goal
// that fails is refused whole (ABORTED with the reason). POSE: the same position and
// heading bounds. CMD_VEL: never non-finite (zero instead), never faster than the
// configured translation / rotation limits. Every check fails for NaN.

#include "common/body_twist.hpp"
#include "common/se2.hpp"
#include "navigator/navigator.hpp"

#include <string>

namespace refloc {

constexpr double kMaxAbsWaypoint_m = 1e4;
constexpr double kMaxAbsHeading_rad = 6.2832;  ///< 2 pi, rounded up
constexpr double kMaxXyTolerance_m = 10.0;
constexpr double kMaxHeadingTolerance_rad = 3.1416;  ///< pi, rounded up
constexpr double kMaxGoalSpeed_m_s = 100.0;

/// Why a goal or pose is refused; kNone: usable. The counter word is to_string's.
enum class NavInputProblem { kNone, kNonFinite, kOutOfBounds };
const char* to_string(NavInputProblem problem);

struct GoalCheck {
  NavInputProblem problem = NavInputProblem::kNone;
  std::string reason;  ///< for NAV_STATUS and the log when refused
};

/// Whether every number of the goal is usable.
GoalCheck check_goal(const NavGoal& goal);

/// Whether a POSE's pose is usable.
NavInputProblem check_pose(const Pose2& map_T_robot);

/// The command as published: zero when any component is not finite, the translation
/// scaled down to max_speed_m_s (keeping its direction), the yaw rate clamped to
/// max_yaw_rate_rad_s. Sets changed when it had to do either.
BodyTwist bounded_command(const BodyTwist& cmd, double max_speed_m_s, double max_yaw_rate_rad_s,
                          bool& changed);

}  // namespace refloc
