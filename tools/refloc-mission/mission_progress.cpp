#include "mission_progress.hpp"

#include <algorithm>

namespace refloc {

MissionProgress::MissionProgress(size_t nwaypoints, const MissionProgressConfig& config)
    : config_(config), nwaypoints_(nwaypoints) {}

bool MissionProgress::needs_send(int64_t now_us) const {
  if (finished_ || reached_ >= nwaypoints_) return false;
  if (!sent_) return true;
  if (lost_) return now_us - last_send_us_ >= config_.lost_goal_resend_us;
  if (!acknowledged_) return now_us - last_send_us_ >= config_.unacknowledged_resend_us;
  // Acknowledged once, silent since: the navigator died and has not come back yet;
  // whoever comes back first gets the goal.
  return now_us - last_status_us_ >= config_.status_timeout_us &&
         now_us - last_send_us_ >= config_.unacknowledged_resend_us;
}

int64_t MissionProgress::start_goal(int64_t goal_id, int64_t now_us) {
  if (sent_) ++resends_;
  // A new id per send: a status for the old goal can never be read as one for the new.
  goal_id_ = sent_ ? std::max(goal_id, goal_id_ + 1) : goal_id;
  offset_ = reached_;
  sent_ = true;
  acknowledged_ = false;
  lost_ = false;
  last_send_us_ = now_us;
  return goal_id_;
}

size_t MissionProgress::on_status(int64_t goal_id, NavStatusState state, int32_t waypoints_reached,
                                  int64_t now_us) {
  if (!sent_ || finished_) return 0;
  if (goal_id != goal_id_) {
    // The navigator knew our goal and now reports IDLE: it restarted (or was
    // replaced) and forgot the goal. Statuses of another sender's active goal are
    // left alone: that commander took over on purpose.
    if (acknowledged_ && state == NavStatusState::kIdle && !lost_) {
      lost_ = true;
      ++goals_lost_;
    }
    return 0;
  }
  acknowledged_ = true;
  last_status_us_ = now_us;
  const size_t total = std::min(nwaypoints_, offset_ + static_cast<size_t>(std::max(0, waypoints_reached)));
  const size_t newly = total > reached_ ? total - reached_ : 0;
  reached_ = std::max(reached_, total);
  if (state == NavStatusState::kArrived && reached_ >= nwaypoints_) finished_ = true;
  if (state == NavStatusState::kAborted) {
    aborted_ = true;
    finished_ = true;
  }
  return newly;
}

}  // namespace refloc
