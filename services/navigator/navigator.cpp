#include "navigator/navigator.hpp"

#include "navigator/navigator_input_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {

const char* to_string(NavState state) {
  switch (state) {
    case NavState::kIdle:
      return "IDLE";
    case NavState::kDriving:
      return "DRIVING";
    case NavState::kArrived:
      return "ARRIVED";
    case NavState::kStoppedNoPose:
      return "STOPPED_NO_POSE";
    case NavState::kAborted:
      return "ABORTED";
  }
  return "?";
}

Navigator::Navigator(const NavigatorConfig& config) : config_(config), translation_(config.translation) {}

namespace {

bool same_goal(const NavGoal& a, const NavGoal& b) {
  if (a.goal_id != b.goal_id || a.waypoints.size() != b.waypoints.size() ||
      a.xy_tolerance != b.xy_tolerance || a.heading_tolerance != b.heading_tolerance ||
      a.max_speed != b.max_speed) {
    return false;
  }
  for (size_t i = 0; i < a.waypoints.size(); ++i) {
    const Waypoint &p = a.waypoints[i], &q = b.waypoints[i];
    if (p.x != q.x || p.y != q.y || p.theta != q.theta) return false;
  }
  return true;
}

}  // namespace

bool Navigator::set_goal(const NavGoal& goal, int64_t now_utime) {
  if (status_.state != NavState::kIdle && same_goal(goal, goal_)) return false;
  stop_output();
  goal_ = goal;
  status_ = NavStatus{};
  status_.goal_id = goal.goal_id;
  status_.nwaypoints = static_cast<int>(goal.waypoints.size());
  if (goal.waypoints.empty()) {
    abort("cancelled: goal without waypoints");
    return true;
  }
  const GoalCheck check = check_goal(goal);
  if (check.problem != NavInputProblem::kNone) {
    abort(check.reason);
    return true;
  }
  xy_tolerance_ = goal.xy_tolerance > 0.0 ? goal.xy_tolerance : config_.default_xy_tolerance;
  heading_tolerance_ =
      goal.heading_tolerance > 0.0 ? goal.heading_tolerance : config_.default_heading_tolerance;
  translation_ = config_.translation;
  if (goal.max_speed > 0.0) translation_.max_speed = std::min(goal.max_speed, translation_.max_speed);
  status_.state = NavState::kDriving;
  best_distance_ = std::numeric_limits<double>::infinity();
  best_heading_error_ = std::numeric_limits<double>::infinity();
  progress_utime_ = now_utime;
  return true;
}

void Navigator::set_pose(const Pose2& map_T_robot, int64_t pose_utime, PoseQuality quality) {
  pose_ = map_T_robot;
  pose_utime_ = pose_utime;
  pose_quality_ = quality;
  has_pose_ = true;
}

void Navigator::abort(const std::string& reason) {
  status_.state = NavState::kAborted;
  status_.reason = reason;
  stop_output();
}

void Navigator::stop_output() {
  map_velocity_.setZero();
  yaw_rate_ = 0.0;
  settled_since_utime_ = -1;
}

bool Navigator::pose_usable(int64_t now_utime, std::string& why_not) const {
  if (!has_pose_) {
    why_not = "no pose received";
    return false;
  }
  const double age = 1e-6 * static_cast<double>(now_utime - pose_utime_);
  if (!(age <= config_.pose_timeout)) {
    why_not = fmt::format("pose is {:.0f} ms old (limit {:.0f} ms)", age * 1e3, config_.pose_timeout * 1e3);
    return false;
  }
  // A pose stamped ahead of the host clock is not "fresh": it would stay so forever.
  if (!(age >= -kMaxPoseAhead_s)) {
    why_not = fmt::format("pose is stamped {:.0f} ms in the future", -age * 1e3);
    return false;
  }
  if (pose_quality_ == PoseQuality::kUnusable ||
      (pose_quality_ == PoseQuality::kDegraded && !config_.drive_on_degraded_pose)) {
    why_not = "pose status is not OK";
    return false;
  }
  return true;
}

BodyTwist Navigator::update(int64_t now_utime) {
  const double dt = last_update_utime_ > 0
                        ? std::clamp(1e-6 * static_cast<double>(now_utime - last_update_utime_), 0.0, 0.1)
                        : 0.02;
  last_update_utime_ = now_utime;
  if (status_.state != NavState::kDriving && status_.state != NavState::kStoppedNoPose) {
    stop_output();
    return {};
  }
  std::string why_not;
  if (!pose_usable(now_utime, why_not)) {
    // Zero at once: the motor controller ramps down under its own limits.
    status_.state = NavState::kStoppedNoPose;
    status_.reason = why_not;
    stop_output();
    progress_utime_ = now_utime;  // waiting for a pose is not a lack of progress
    return {};
  }
  status_.state = NavState::kDriving;
  status_.reason.clear();
  return drive(now_utime, dt);
}

BodyTwist Navigator::drive(int64_t now_utime, double dt) {
  const Waypoint& target = goal_.waypoints[static_cast<size_t>(status_.waypoint_index)];
  const Eigen::Vector2d error(target.x - pose_.x, target.y - pose_.y);
  const double distance = error.norm();
  const double heading_error = angle_diff(target.theta, pose_.theta);
  status_.distance_to_waypoint = distance;
  status_.heading_error = heading_error;

  // Settle check: inside both tolerances for settle_time in a row.
  if (distance <= xy_tolerance_ && std::abs(heading_error) <= heading_tolerance_) {
    if (settled_since_utime_ < 0) settled_since_utime_ = now_utime;
    if (1e-6 * static_cast<double>(now_utime - settled_since_utime_) >= config_.settle_time) {
      ++status_.waypoints_reached;
      stop_output();
      if (status_.waypoints_reached == status_.nwaypoints) {
        status_.state = NavState::kArrived;
        return {};
      }
      ++status_.waypoint_index;
      best_distance_ = std::numeric_limits<double>::infinity();
      best_heading_error_ = std::numeric_limits<double>::infinity();
      progress_utime_ = now_utime;
      return {};
    }
  } else {
    settled_since_utime_ = -1;
  }

  if (distance < best_distance_ - 0.005 || std::abs(heading_error) < best_heading_error_ - 0.01) {
    best_distance_ = std::min(best_distance_, distance);
    best_heading_error_ = std::min(best_heading_error_, std::abs(heading_error));
    progress_utime_ = now_utime;
  } else if (1e-6 * static_cast<double>(now_utime - progress_utime_) > config_.progress_timeout &&
             distance > xy_tolerance_) {
    abort(fmt::format("no progress toward waypoint {} for {:.0f} s", status_.waypoint_index,
                      config_.progress_timeout));
    return {};
  }

  const Eigen::Vector2d wanted_velocity =
      distance > 1e-9 ? Eigen::Vector2d(error * (approach_speed(distance, translation_) / distance))
                      : Eigen::Vector2d::Zero();
  map_velocity_ = rate_limit(map_velocity_, wanted_velocity, translation_.max_accel * dt);
  const double wanted_yaw_rate =
      std::copysign(approach_speed(std::abs(heading_error), config_.rotation), heading_error);
  yaw_rate_ = rate_limit(yaw_rate_, wanted_yaw_rate, config_.rotation.max_accel * dt);

  // The profile lives in the map frame; CMD_VEL is in the body frame.
  const Eigen::Vector2d body_velocity = pose_.rotation().transpose() * map_velocity_;
  return {body_velocity.x(), body_velocity.y(), yaw_rate_};
}

}  // namespace refloc
