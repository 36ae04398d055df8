#pragma once
// Which waypoints of a mission have been reached, across navigator restarts.
//
// The navigator keeps its goal in memory only: a restarted navigator reports
// IDLE (or nothing) and the robot stands still. The mission sender is the one
// that knows the mission, so it resends the remaining waypoints under a new
// goal id, and counts the navigator's waypoints_reached from that offset.

#include <cstddef>
#include <cstdint>

namespace refloc {

struct MissionProgressConfig {
  int64_t unacknowledged_resend_us = 1'000'000;  ///< resend while no NAV_STATUS names the goal [us]
  int64_t lost_goal_resend_us = 200'000;         ///< min. time between resends after a lost goal [us]
  int64_t status_timeout_us = 2'000'000;         ///< no NAV_STATUS for the goal this long: assume lost [us]
};

/// NAV_STATUS state values (nav_status_t::STATE_*), without the LCM type.
enum class NavStatusState : int8_t {
  kIdle = 0,
  kDriving = 1,
  kArrived = 2,
  kStoppedNoPose = 3,
  kAborted = 4
};

class MissionProgress {
 public:
  MissionProgress(size_t nwaypoints, const MissionProgressConfig& config = {});

  /// Whether a goal should be (re)sent at now_us [monotonic us].
  bool needs_send(int64_t now_us) const;
  /// A goal with waypoints [first_waypoint(), nwaypoints) is sent now under goal_id
  /// (made unique: larger than every id sent before). Returns the id to use.
  int64_t start_goal(int64_t goal_id, int64_t now_us);
  /// A NAV_STATUS arrived at now_us. Returns the number of waypoints newly reached.
  size_t on_status(int64_t goal_id, NavStatusState state, int32_t waypoints_reached, int64_t now_us);

  size_t reached() const { return reached_; }
  /// Index of the first waypoint of the current goal.
  size_t first_waypoint() const { return offset_; }
  int64_t goal_id() const { return goal_id_; }
  bool finished() const { return finished_; }
  bool aborted() const { return aborted_; }
  /// Goals resent because the navigator lost or never acknowledged the current one.
  int resends() const { return resends_; }
  /// Times the navigator was seen to have lost an acknowledged goal (a restart).
  int goals_lost() const { return goals_lost_; }

 private:
  MissionProgressConfig config_;
  size_t nwaypoints_;
  size_t reached_ = 0;
  size_t offset_ = 0;
  int64_t goal_id_ = 0;
  int64_t last_send_us_ = 0;
  int64_t last_status_us_ = 0;
  bool sent_ = false;
  bool acknowledged_ = false;
  bool lost_ = false;
  bool finished_ = false;
  bool aborted_ = false;
  int resends_ = 0;
  int goals_lost_ = 0;
};

}  // namespace refloc
