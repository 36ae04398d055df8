#pragma once
// The direct odometry calibration: every laser fix against odometry integrated from the encoder
// steps with the scales applied step by step. The drive is cut into segments; in segment k
//   map_T_laser(t) = map_T_segment_k * P(s_r, s_k; steps from the segment start to t) * robot_T_laser
// where P integrates each nominal step's body displacement (vx, vy, wz) as (s_r vx, s_r vy,
// s_r / s_k wz). This is exact for any motion (refloc-calibrate-mount's direct model scales
// the end pose of odom_k_T_robot instead, which is only exact on straight legs and in place:
// with the true poses as fixes it gave lx + ly 0.04-0.06 % low on the calibration drive).
// The mount is held (refloc-calibrate-mount's). Each fix's residual is whitened by its
// LASER_POSE covariance (through the lever arm) plus the odometry noise model over the path
// driven and the angle turned since the segment's start.
//
// Sigma: consecutive fixes' errors can be correlated (same reflectors, the solver's tracking),
// so the least-squares covariance (J^T W J)^-1 x max(1, chi2/dof) is multiplied by the
// residuals' measured correlation factor 1 + 2 sum_k rho_k (the integrated autocorrelation of
// the whitened residuals within segments, summed while positive): the number of effectively
// independent fixes is the count divided by that factor. Fix errors that are a smooth function
// of the position (sub-millimetre on the simulated drives) are not seen by it: they are what
// long straight legs are for (see README.md).

#include "calibration_pairs.hpp"
#include "common/odometry_noise.hpp"
#include "common/robot_config.hpp"
#include "odometry_calibration.hpp"

namespace refloc {

struct DirectOdometryOptions {
  /// Length of one segment with its own start pose [s]: long enough to hold a whole straight leg
  /// (the scales act only within a segment); odometry drift is weighted by the noise model.
  double segment_s = 30.0;
  double max_fix_gap_s = 0.25;           ///< a longer gap between fixes or encoder samples ends a segment [s]
  double min_total_rotation_rad = 3.0;   ///< below this turned, s_k is not observable [rad]
  double min_total_translation_m = 1.0;  ///< below this driven, s_r is not observable [m]
  size_t max_correlation_lag = 200;      ///< longest lag of the residual autocorrelation [fixes]
};

/// laser_fixes as LASER_POSE gives them (map_T_robot with configured_robot_T_laser); the fixes
/// are read with robot_T_laser (held). nominal: kinematics, ticks and odometry noise.
OdometryCalibrationResult calibrate_odometry_exact(const CalibrationDrive& drive, const RobotConfig& nominal,
                                                   const Pose2& configured_robot_T_laser,
                                                   const Pose2& robot_T_laser,
                                                   const DirectOdometryOptions& options);

}  // namespace refloc
