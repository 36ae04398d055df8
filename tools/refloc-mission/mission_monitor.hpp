#pragma once
// What refloc-mission watches while a mission runs, without LCM: GROUND_TRUTH, and
// POSE / LASER_POSE (with their covariances) / ODOMETRY recorded while driving; the
// navigator's progress (MissionProgress: which goal to send when); the true arrival error
// at each waypoint; pose_solver's range bias estimate from HEARTBEAT; the timeout; and the
// report (JSON, the plot's trace).

#include "heartbeat_table.hpp"
#include "mission_file.hpp"
#include "mission_progress.hpp"
#include "path_plot_trace.hpp"
#include "trajectory.hpp"
#include "trajectory_consistency.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace refloc {

struct WaypointResult {
  Pose2 target;
  bool reached = false;
  double error_xy_m = NAN;         ///< true position error when reached (GROUND_TRUTH) [m]
  double error_heading_rad = NAN;  ///< true heading error when reached [rad]
  int64_t reached_utime = 0;       ///< stamp of the GROUND_TRUTH it was judged by [us]
};

/// A NAV_GOAL to publish (nav_goal_t without the LCM type): the waypoints not reached yet.
struct GoalRequest {
  int64_t utime = 0;  ///< when it was made [us, wall clock]
  int64_t goal_id = 0;
  size_t first_waypoint = 0;                ///< mission index of the first waypoint below
  std::vector<double> x_m, y_m, theta_rad;  ///< the waypoints, map frame
  double xy_tolerance_m = 0.0;
  double heading_tolerance_rad = 0.0;
  double max_speed_m_s = 0.0;
  bool resend = false;  ///< an earlier goal was lost (navigator restarted) or never acknowledged
};

class MissionMonitor {
 public:
  explicit MissionMonitor(Mission mission, const MissionProgressConfig& progress = {});

  void on_ground_truth(int64_t utime, const Pose2& map_T_robot);
  /// POSE; `ok`: status OK. The first OK pose means localized. covariance: the message's,
  /// of (x [m], y [m], theta [rad]), for the NEES against GROUND_TRUTH.
  void on_pose(int64_t utime, const Pose2& map_T_robot, bool ok, const Eigen::Matrix3d& covariance);
  void on_laser_pose(int64_t utime, const Pose2& map_T_robot, bool ok, const Eigen::Matrix3d& covariance);
  /// HEARTBEAT of any service; pose_solver's gauges range_bias_um / range_bias_sigma_um are kept.
  void on_heartbeat(const HeartbeatSample& heartbeat);
  /// ODOMETRY; a distance below the previous one is a restarted odometry service, whose
  /// new frame starts the drift measurement again.
  void on_odometry(int64_t utime, const Pose2& odom_T_robot, double distance_m);
  /// NAV_STATUS at now_us [monotonic us] while driving; returns the mission indices of
  /// the waypoints it newly reached (their errors are in result()).
  std::vector<size_t> on_status(int64_t goal_id, NavStatusState state, int32_t waypoints_reached,
                                const std::string& reason, int64_t now_us);

  bool localized() const { return localized_; }
  /// Waiting for the first OK POSE from now_us [monotonic us] on.
  void start_waiting(int64_t now_us) { wait_start_us_ = now_us; }
  /// Waited longer than the mission's localization_timeout_s.
  bool localization_timed_out(int64_t now_us) const {
    return now_us - wait_start_us_ > static_cast<int64_t>(mission_.localization_timeout_s * 1e6);
  }
  /// Driving starts at utime [us, wall clock] / now_us [monotonic us]: poses are recorded from here.
  void start_driving(int64_t utime, int64_t now_us);
  /// The goal to publish now (its id made from utime), if one is due: the first, a resend
  /// while the navigator has not acknowledged it (UDP has no last value for late joiners),
  /// or the remaining waypoints after a restarted navigator forgot them.
  std::optional<GoalRequest> goal_due(int64_t utime, int64_t now_us);
  /// True once the mission has driven longer than its timeout (recorded as the abort reason).
  bool timed_out(int64_t now_us);
  /// Still driving: not finished, not timed out.
  bool driving() const { return driving_ && !progress_.finished() && abort_reason_.empty(); }
  void stop_driving(int64_t utime);

  const Mission& mission() const { return mission_; }
  const WaypointResult& result(size_t i) const { return results_[i]; }
  bool all_reached() const;

  /// The JSON refloc-mission --json writes (scripts read its keys).
  nlohmann::json report(const std::string& log_file) const;
  /// Ground truth, POSE and LASER_POSE (with their errors) while driving, and the waypoints, for the plot.
  PathTrace path_trace() const;

 private:
  /// Odometry alone, anchored to the truth at the first odometry sample of the run [m].
  double odometry_drift_m() const;

  Mission mission_;
  MissionProgress progress_;
  std::vector<WaypointResult> results_;
  Trajectory truth_, pose_, laser_pose_, odometry_;
  std::vector<StampedFix> pose_fixes_, laser_fixes_;         ///< pose_ and laser_pose_ with covariances
  std::optional<double> range_bias_m_, range_bias_sigma_m_;  ///< pose_solver's latest [m]
  Pose2 latest_truth_;
  int64_t latest_truth_utime_ = 0;
  bool has_truth_ = false;
  bool localized_ = false;
  bool driving_ = false;
  double last_odometry_distance_m_ = 0.0;
  int odometry_restarts_ = 0;
  int64_t drive_start_utime_ = 0;
  int64_t drive_end_utime_ = 0;
  int64_t drive_start_us_ = 0;
  int64_t wait_start_us_ = 0;
  std::string abort_reason_;
};

}  // namespace refloc
