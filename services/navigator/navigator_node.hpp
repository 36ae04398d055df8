#pragma once
// The navigator service without LCM: NAV_GOAL and POSE in as they arrive, a
// control tick at the control rate and a status tick at the status rate; out,
// the CMD_VEL to publish (commands continue, zero once done, for half a second
// after a goal ends, then stop so another commander may drive), the NAV_STATUS
// to publish (on every change, and on each status tick), counters and log lines,
// and the heartbeat state (DEGRADED while stopped for want of a pose).
//
// Inputs are judged first (navigator_input_checks.hpp): a refused goal is ABORTED and
// counted (goals_refused and rejected_nav_goal_<reason>); a POSE with a non-finite or
// absurd pose, or a stamp its StampGuard refuses, is skipped and counted
// (rejected_pose_<reason>), so the last good pose ages out and the robot stops. The
// NAV_GOAL stamp is not read (a goal starts when it arrives). Every CMD_VEL is bounded
// (bounded_command): a non-finite one becomes zero (commands_nonfinite_zeroed), one
// above the configured limits is clamped (commands_clamped).

#include "common/node_event.hpp"
#include "common/stamp_guard.hpp"
#include "navigator/navigator.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace refloc {

/// What one call wants published.
struct NavigatorOutput {
  std::optional<BodyTwist> command;   ///< CMD_VEL
  const NavStatus* status = nullptr;  ///< NAV_STATUS; nullptr: none
};

struct NavigatorHealth {
  bool ok = true;
  std::string detail;  ///< why stopped
};

class NavigatorNode {
 public:
  /// After a goal ends, commands continue this long [us].
  static constexpr int64_t kCommandHoldUs = 500'000;

  explicit NavigatorNode(const NavigatorConfig& config);

  /// A NAV_GOAL at now_utime [us]. A republished, already running goal changes nothing.
  NavigatorOutput on_goal(const NavGoal& goal, int64_t now_utime);
  /// A POSE: map_T_robot at pose_utime [us] with its quality, arriving at host_utime (the
  /// host's wall clock [us]); its counters and warnings are in events().
  void on_pose(const Pose2& map_T_robot, int64_t pose_utime, PoseQuality quality, int64_t host_utime);
  /// One control period at now_utime [us].
  NavigatorOutput on_control_tick(int64_t now_utime);
  /// The periodic NAV_STATUS (published whether or not it changed).
  NavigatorOutput on_status_tick();

  /// Counters and log lines of the last on_goal / on_pose / on_control_tick / on_status_tick.
  const std::vector<NodeEvent>& events() const { return events_; }
  NavigatorHealth health() const;
  const Navigator& navigator() const { return navigator_; }

 private:
  /// The status to publish: always, or (only_on_change) when state, goal, progress or reason changed.
  const NavStatus* status_to_publish(bool only_on_change);

  Navigator navigator_;
  StampGuard pose_stamps_;
  NavStatus published_;
  bool published_once_ = false;
  int64_t last_active_utime_ = 0;
  std::vector<NodeEvent> events_;
};

}  // namespace refloc
