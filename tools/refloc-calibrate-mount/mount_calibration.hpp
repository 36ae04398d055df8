#pragma once
// Estimates the laser mount robot_T_laser (x, y, yaw; the paper's eq. 8, OO' and beta) from a
// drive: hand-eye calibration A X = X B in SE(2), A = the robot's motion over a window from
// odometry, B = the laser's motion over the same window from laser fixes, X = robot_T_laser.
//
// In the plane the rotation part of A X = X B says only theta_A = theta_B, nothing about X; the
// translation part is  R_X t_B - t_A = (R_B - I) t_X. Rotating in place (R_B != I) gives t_X;
// straight legs (R_B = I) give the yaw, R_X t_B = t_A. The laser's own theta_B is used in
// (R_B - I), not the odometry's: odometry heading scales with the (lx + ly) error, the laser's
// does not. Odometry translation t_A is multiplied by an estimated scale s (the wheel radius
// error), so a wrong radius does not bias the mount.
//
// Weighting: each window's 2-vector residual is whitened by its covariance
//   R_X Cov(t_B) R_X^T + Cov(t_A) + (dR_B/dtheta t_X) var(theta_B) (.)^T
// with Cov(t_B), var(theta_B) from the two fixes' covariances and Cov(t_A) from the robot's
// odometry noise model (robot.json "odometry_noise", per metre driven and radian turned).
// The weights are re-evaluated once at the first solution. The reported covariance is Ceres'
// (J^T W J)^-1 scaled by chi^2/dof when that is > 1, so unmodelled errors widen the sigma.

#include "calibration_pairs.hpp"
#include "common/odometry_noise.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

/// One window: the robot's motion from odometry and the laser's from the fixes.
struct MountWindow {
  Pose2 odometry_first_T_last;   ///< A: robot motion from odometry (robot frame at the start)
  TimedPose laser_first_T_last;  ///< B: laser motion (laser frame at the start) with covariance
};

struct MountCalibrationOptions {
  Pose2 initial_robot_T_laser;             ///< start of the search (the configured mount)
  bool estimate_translation_scale = true;  ///< estimate odometry's translation scale s (else s = 1)
  OdometryNoise odometry_noise;            ///< weights of the odometry translations
  double min_total_rotation_rad = 3.0;     ///< below this turned, x and y are not observable [rad]
  double min_total_translation_m = 1.0;    ///< below this driven straight, yaw is not observable [m]
};

struct MountCalibrationResult {
  bool ok = false;
  std::string message;  ///< why not ok, or the solver's summary line
  Pose2 robot_T_laser;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< (x, y, theta) [m^2, m rad, rad^2]
  double translation_scale = 1.0;                        ///< s: laser translation / odometry translation
  double translation_scale_sigma = 0.0;
  double heading_scale = 1.0;  ///< direct only: h, laser rotation / odometry rotation
  Eigen::Matrix2d scales_covariance = Eigen::Matrix2d::Zero();  ///< direct only: of (s, h)
  double chi2_per_dof = 0.0;
  size_t windows = 0;
  double total_rotation_rad = 0.0;   ///< sum of |theta_B| over the windows
  double total_translation_m = 0.0;  ///< sum of |t_B| over windows turning < 0.05 rad
};

/// Solve robot_T_laser from the windows (needs rotation in place and straight legs).
MountCalibrationResult calibrate_mount(const std::vector<MountWindow>& windows,
                                       const MountCalibrationOptions& options);

/// The windows of a drive: laser fixes (map_T_robot computed with configured_robot_T_laser,
/// undone here to map_T_laser) against odometry interpolated at the fixes' stamps.
std::vector<MountWindow> mount_windows(const CalibrationDrive& drive, const Pose2& configured_robot_T_laser,
                                       const WindowOptions& options);

}  // namespace refloc
