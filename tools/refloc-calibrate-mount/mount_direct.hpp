#pragma once
// The direct formulation of the mount calibration, using every laser fix (the hand-eye windows of
// mount_calibration.hpp use, in effect, only the ends of each leg: the inner fixes of
// consecutive windows cancel). The drive is cut into segments of a few seconds; in segment k
//   map_T_laser(t) = map_T_segment_k * S(odom_k_T_robot(t)) * robot_T_laser
// with map_T_segment_k unknown (3 per segment, so odometry drift never spans more than one
// segment) and S scaling odometry's translation by s and its heading by h (wheel radius and
// lx + ly errors). Each fix's residual (x, y, theta) is whitened by its own covariance plus the
// odometry noise model's covariance of odom_k_T_robot(t). Sigma as in calibrate_mount.

#include "mount_calibration.hpp"

namespace refloc {

struct DirectMountOptions {
  MountCalibrationOptions mount;  ///< initial mount, noise model, observability limits
  double segment_s = 4.0;         ///< length of one segment with its own start pose [s]
  double max_fix_gap_s = 0.25;    ///< a longer gap between fixes ends the segment [s]
  bool hold_mount = false;        ///< keep mount.initial_robot_T_laser (solve s, h only)
};

/// laser_fixes as LASER_POSE gives them (map_T_robot with configured_robot_T_laser).
MountCalibrationResult calibrate_mount_direct(const CalibrationDrive& drive,
                                              const Pose2& configured_robot_T_laser,
                                              const DirectMountOptions& options);

}  // namespace refloc
