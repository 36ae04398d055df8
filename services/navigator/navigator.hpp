#pragma once
// Drives the holonomic base through a list of waypoints: translation along the
// straight line to the waypoint and rotation to its heading, each under its own
// trapezoidal profile, commanded as a body twist. Stops (zero twist) whenever
// the pose is stale or not usable, and resumes when it is good again.
//
// The caller feeds poses and goals as they arrive and calls update(now) once
// per control period; all time comes from the arguments, so tests drive it.

#include "common/se2.hpp"
#include "navigator/trapezoid_profile.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

struct NavigatorConfig {
  ProfileLimits translation{1.0, 0.5, 0.8, 0.03, 0.03, 2.0};  ///< [m/s, m/s^2, -, m, m/s, 1/s]
  ProfileLimits rotation{1.0, 1.0, 0.8, 0.05, 0.05, 2.0};     ///< [rad/s, rad/s^2, -, rad, rad/s, 1/s]
  double pose_timeout = 0.2;                                  ///< a pose older than this stops the robot [s]
  double settle_time = 0.2;             ///< within tolerance this long = waypoint reached [s]
  double progress_timeout = 30.0;       ///< abort when the waypoint gets no closer this long [s]
  double default_xy_tolerance = 0.010;  ///< [m]
  double default_heading_tolerance = deg_to_rad(0.5);  ///< [rad]
  bool drive_on_degraded_pose = false;                 ///< accept fused poses without a recent laser fix
};

struct Waypoint {
  double x = 0.0;      ///< [m] map frame
  double y = 0.0;      ///< [m]
  double theta = 0.0;  ///< [rad]
};

struct NavGoal {
  int64_t goal_id = 0;
  std::vector<Waypoint> waypoints;  ///< empty = cancel the current goal
  double xy_tolerance = 0.0;        ///< [m]; <= 0: the default
  double heading_tolerance = 0.0;   ///< [rad]; <= 0: the default
  double max_speed = 0.0;           ///< [m/s]; <= 0: the configured limit
};

/// Values match nav_status_t's STATE_* constants.
enum class NavState : int8_t { kIdle = 0, kDriving = 1, kArrived = 2, kStoppedNoPose = 3, kAborted = 4 };

struct NavStatus {
  int64_t goal_id = 0;
  NavState state = NavState::kIdle;
  int waypoint_index = 0;
  int waypoints_reached = 0;
  int nwaypoints = 0;
  double distance_to_waypoint = 0.0;  ///< [m]
  double heading_error = 0.0;         ///< waypoint heading minus robot heading [rad]
  std::string reason;                 ///< why ABORTED or STOPPED_NO_POSE
};

/// How usable a pose is for driving.
enum class PoseQuality { kGood, kDegraded, kUnusable };

class Navigator {
 public:
  /// A pose stamped this far ahead of now is not usable [s].
  static constexpr double kMaxPoseAhead_s = 0.1;

  explicit Navigator(const NavigatorConfig& config);

  /// Start a new goal (replacing any current one) at now_utime [us]. An empty
  /// goal cancels; a goal with non-finite or absurd values is refused (ABORTED with reason, check_goal).
  /// The same goal again (same id and content, as a sender republishing it for
  /// late joiners does) is ignored: returns false.
  bool set_goal(const NavGoal& goal, int64_t now_utime);
  /// The latest map_T_robot, the time it refers to [us] and its quality.
  void set_pose(const Pose2& map_T_robot, int64_t pose_utime, PoseQuality quality);
  /// One control period: the body twist to command now [m/s, m/s, rad/s].
  BodyTwist update(int64_t now_utime);

  const NavStatus& status() const { return status_; }
  const NavigatorConfig& config() const { return config_; }

 private:
  bool pose_usable(int64_t now_utime, std::string& why_not) const;
  BodyTwist drive(int64_t now_utime, double dt);
  void abort(const std::string& reason);
  void stop_output();

  NavigatorConfig config_;
  NavStatus status_;
  NavGoal goal_;
  double xy_tolerance_ = 0.0;
  double heading_tolerance_ = 0.0;
  ProfileLimits translation_;
  Pose2 pose_;
  int64_t pose_utime_ = 0;
  PoseQuality pose_quality_ = PoseQuality::kUnusable;
  bool has_pose_ = false;
  int64_t last_update_utime_ = 0;
  Eigen::Vector2d map_velocity_ = Eigen::Vector2d::Zero();  ///< last command [m/s]
  double yaw_rate_ = 0.0;                                   ///< last command [rad/s]
  int64_t settled_since_utime_ = -1;
  double best_distance_ = 0.0;
  double best_heading_error_ = 0.0;
  int64_t progress_utime_ = 0;
};

const char* to_string(NavState state);

}  // namespace refloc
