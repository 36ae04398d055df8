#pragma once
// The pose line of refloc-status: the last POSE (status, x, y, theta, its 1-sigma) and how
// many laser fixes per second LASER_POSE brings. Plain data in, no LCM (main.cpp converts).

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <string>

namespace refloc {

/// One pose2d_t as plain data.
struct PoseSample {
  int64_t utime = 0;  ///< [us]
  double x_m = 0.0;
  double y_m = 0.0;
  double theta_rad = 0.0;
  std::array<double, 9> covariance{};  ///< row-major (x, y, theta) [m^2, m rad, rad^2]
  int8_t status = 0;                   ///< pose2d_t::STATUS_*
};

/// Name of a pose2d_t::STATUS_* value ("OK", "DEGRADED", "LOST", ...; "STATUS_9" if unknown).
std::string pose_status_name(int8_t status);

/// What the pose line shows at one moment.
struct PoseReport {
  bool heard = false;  ///< a POSE was received
  PoseSample last;
  double age_s = 0.0;              ///< since the last POSE was received [s]
  bool stale = false;              ///< older than the heartbeat limit
  double sigma_position_m = -1.0;  ///< sqrt of the largest eigenvalue of the x-y block; < 0: unusable
  double sigma_theta_rad = -1.0;   ///< < 0: unusable
  double fixes_ok_per_s = 0.0;     ///< LASER_POSE with status OK per second, over the fix window
  double laser_poses_per_s = 0.0;  ///< every LASER_POSE per second, over the fix window
};

class PoseWatch {
 public:
  /// start_s: when listening began (the rate window is shorter until fix_window_s has passed).
  PoseWatch(double start_s, double max_age_s, double fix_window_s = 2.0);

  void on_pose(const PoseSample& pose, double receive_s);
  void on_laser_pose(int8_t status, double receive_s);
  PoseReport report(double now_s) const;

 private:
  struct Fix {
    double receive_s;
    bool ok;
  };
  double start_s_;
  double max_age_s_;
  double fix_window_s_;
  bool heard_ = false;
  PoseSample last_;
  double last_receive_s_ = 0.0;
  std::deque<Fix> fixes_;  ///< LASER_POSE receive times of the last fix_window_s
};

/// "POSE OK x 1.234 y -0.567 m, theta 12.34 deg, sigma 3.1 mm 0.05 deg, fixes 9.8/s OK of 10.0/s"
/// (fixes: LASER_POSE per second with status OK, of all LASER_POSE per second), "POSE STALE (OK
/// 4.2 s ago) ..." or "POSE none heard, ...". 93 columns for an OK pose; the page wraps longer ones.
std::string format_pose_line(const PoseReport& report);

/// {"heard", "status", "x_m", "y_m", "theta_rad", "sigma_position_m", "sigma_theta_rad", "age_s",
///  "stale", "fixes_ok_per_s", "laser_poses_per_s"}; pose fields null when none was heard.
nlohmann::json pose_to_json(const PoseReport& report);

}  // namespace refloc
