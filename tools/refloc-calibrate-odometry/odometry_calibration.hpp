#pragma once
// Estimates the wheel radius scale s_r and the (lx + ly) geometry scale s_k of a Mecanum base
// from laser fixes over a drive. The forward kinematics (common/mecanum_kinematics.hpp) is
// linear in r for (vx, vy) and in r / (lx + ly) for wz, so with the nominal robot's twist
// (vx, vy, wz) from the wheel angles the true one is (s_r vx, s_r vy, s_r / s_k wz). Over each
// window between two laser fixes the encoder steps are integrated (SE(2) exp per step) with the
// scaled twists and compared with the robot's motion from the fixes: a 3-vector residual
// log(A(s_r, s_k)^-1 B), whitened by Cov(B) from the fixes plus the odometry noise model's
// increment covariance. Only lx + ly is observable; the corrected lx, ly keep their ratio.
// The covariance is scaled by chi^2/dof when that is > 1 (as in refloc-calibrate-mount).

#include "calibration_pairs.hpp"
#include "common/mecanum_kinematics.hpp"
#include "common/robot_config.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

/// One window: the nominal body displacements of its encoder steps and the laser's robot motion.
struct OdometryWindow {
  std::vector<BodyTwist> nominal_steps;  ///< per encoder step, nominal kinematics, [m, m, rad]
  TimedPose laser_first_T_last;          ///< robot motion from the fixes, with covariance
};

struct OdometryCalibrationOptions {
  OdometryNoise odometry_noise;          ///< weights of the odometry increments
  double min_total_rotation_rad = 3.0;   ///< below this turned, s_k is not observable [rad]
  double min_total_translation_m = 1.0;  ///< below this driven, s_r is not observable [m]
};

struct OdometryCalibrationResult {
  bool ok = false;
  std::string message;
  double radius_scale = 1.0;                             ///< s_r: true wheel radius / configured
  double geometry_scale = 1.0;                           ///< s_k: true (lx + ly) / configured
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< of (s_r, s_k)
  double chi2_per_dof = 0.0;
  double correlation_factor = 1.0;  ///< direct: covariance inflation for correlated fix errors
  size_t windows = 0;
  double total_rotation_rad = 0.0;
  double total_translation_m = 0.0;
};

/// The robot's motion over a window of nominal steps with the scales applied.
Pose2 integrate_scaled(const std::vector<BodyTwist>& nominal_steps, double radius_scale,
                       double geometry_scale);

OdometryCalibrationResult calibrate_odometry(const std::vector<OdometryWindow>& windows,
                                             const OdometryCalibrationOptions& options);

/// The windows of a drive. laser_fixes are map_T_robot (already with the mount the caller
/// trusts); each encoder step overlapping a window contributes the overlapping fraction.
std::vector<OdometryWindow> odometry_windows(const CalibrationDrive& drive, const RobotConfig& nominal,
                                             const WindowOptions& options);

/// Odometry recomputed from the encoders with the nominal kinematics (what mecanum_odometry
/// does, without its noise handling): odom_T_robot at every encoder stamp.
std::vector<TimedPose> encoder_odometry(const std::vector<EncoderSample>& encoders,
                                        const RobotConfig& nominal);

/// The end-pose solution (--method direct-endpoint; every fix, refloc-calibrate-mount's
/// mount_direct.hpp on encoder odometry): its odometry scales s (translation) and h (heading) are
/// s_r and s_r / s_k. Approximate when a segment turns and translates; the default is
/// calibrate_odometry_exact (odometry_direct.hpp). robot_T_laser:
/// the calibrated mount, held; the drive's laser_fixes as LASER_POSE gives them (with
/// configured_robot_T_laser).
OdometryCalibrationResult calibrate_odometry_direct(const CalibrationDrive& drive, const RobotConfig& nominal,
                                                    const Pose2& configured_robot_T_laser,
                                                    const Pose2& robot_T_laser, double segment_s);

/// The robot with the scales applied: wheel_radius * s_r, lx and ly each * s_k.
RobotConfig corrected_robot(const RobotConfig& nominal, double radius_scale, double geometry_scale);

}  // namespace refloc
