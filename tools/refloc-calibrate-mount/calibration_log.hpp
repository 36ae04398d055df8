#pragma once
// Reads a calibration drive from an LCM log: the one place the calibration tools decode
// lcmtypes. Laser fixes that are not STATUS_OK are left out and counted.

#include "calibration_pairs.hpp"

#include <string>

namespace refloc {

struct CalibrationChannels {
  std::string odometry = "ODOMETRY";        ///< odometry_t (mecanum_odometry)
  std::string laser_pose = "LASER_POSE";    ///< pose2d_t, map_T_robot with the configured mount
  std::string encoders = "WHEEL_ENCODERS";  ///< wheel_encoders_t
};

struct CalibrationLogCounts {
  size_t odometry = 0;
  size_t laser_fixes_ok = 0;
  size_t laser_fixes_not_ok = 0;  ///< LASER_POSE with any status but OK: not used
  size_t encoders = 0;
  size_t undecodable = 0;  ///< messages on those channels that did not decode
};

/// Throws ConfigError when the log cannot be opened. Series are sorted by utime.
CalibrationDrive read_calibration_log(const std::string& path, const CalibrationChannels& channels,
                                      CalibrationLogCounts& counts);

}  // namespace refloc
