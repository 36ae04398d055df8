#pragma once
// What both calibration tools (refloc-calibrate-mount, refloc-calibrate-odometry) read from a
// drive: time series of poses and encoder counts, plain structs without LCM, and the windows
// between two laser fixes over which odometry and laser motion are compared. One place so the
// two tools cut the drive the same way.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace refloc {

/// A stamped pose with its 3x3 covariance (x, y, theta) [m^2, m rad, rad^2].
struct TimedPose {
  int64_t utime = 0;  ///< [us]
  Pose2 pose;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
};

/// Cumulative wheel encoder counts (front-left, front-right, rear-right, rear-left).
struct EncoderSample {
  int64_t utime = 0;  ///< [us]
  std::array<int32_t, 4> ticks{};
};

/// A calibration drive: odometry (odom_T_robot), laser fixes (map_T_robot from LASER_POSE,
/// status OK only) and encoder counts, each sorted by utime.
struct CalibrationDrive {
  std::vector<TimedPose> odometry;
  std::vector<TimedPose> laser_fixes;
  std::vector<EncoderSample> encoders;
};

/// When a window between two laser fixes ends: as soon as one of the limits is reached.
struct WindowOptions {
  double min_translation_m = 0.15;  ///< laser translation that closes a window [m]
  double min_rotation_rad = 0.25;   ///< laser rotation that closes a window [rad]
  double max_duration_s = 1.0;      ///< a window never spans longer [s]
  double max_fix_gap_s = 0.25;      ///< two fixes further apart break the window [s]
};

/// A pair of laser fixes (indices into laser_fixes) whose motion is compared with odometry.
struct FixWindow {
  size_t first = 0;
  size_t last = 0;
};

/// Consecutive, non-overlapping windows (so their errors are independent) over the fixes.
/// Windows with no motion are kept: they carry information about the odometry's noise only.
std::vector<FixWindow> select_fix_windows(const std::vector<TimedPose>& laser_fixes,
                                          const WindowOptions& options);

/// Pose at utime, linearly interpolated (heading along the short arc); nullopt outside the
/// series or across a gap longer than max_gap_s.
std::optional<Pose2> interpolate_pose(const std::vector<TimedPose>& series, int64_t utime, double max_gap_s);

/// map_T_laser = map_T_robot * robot_T_laser with its covariance (the lever arm turns heading
/// uncertainty into position uncertainty).
TimedPose compose_mount(const TimedPose& map_T_robot, const Pose2& robot_T_laser);

/// first_T_last = map_T_first^-1 * map_T_last with the covariance of its (x, y, theta), the two
/// fixes taken as independent.
TimedPose relative_pose(const TimedPose& map_T_first, const TimedPose& map_T_last);

/// Encoder counts to wheel angles [rad]; int32 wrap-around is undone per step.
std::array<double, 4> wheel_angle_delta(const EncoderSample& from, const EncoderSample& to,
                                        int ticks_per_rev);

}  // namespace refloc
