#pragma once
// refloc-calibrate-odometry's work: read the drive from a log, solve the wheel radius and
// (lx + ly) scales, print them and the corrected robot.json values.

#include "calibration_log.hpp"
#include "odometry_direct.hpp"

#include <optional>
#include <string>

namespace refloc {

struct OdometryCommandOptions {
  std::string log_path;
  std::string robot_path = "deploy/config/robot.json";  ///< the robot file the services ran with
  std::string json_path;                                ///< also write the result here
  /// The mount to read LASER_POSE with, when it differs from the robot file's (e.g. the output
  /// of refloc-calibrate-mount on the same drive); LASER_POSE was computed with the file's.
  std::optional<Pose2> robot_T_laser;
  /// "direct" (every fix, odometry integrated step by step with the scales, odometry_direct.hpp),
  /// "direct-endpoint" (refloc-calibrate-mount's model: the end pose scaled) or "windows" (fix pairs)
  std::string method = "direct";
  double segment_s = DirectOdometryOptions{}.segment_s;  ///< direct, direct-endpoint: segment length [s]
  CalibrationChannels channels;
  /// Simulation only: the true-pose channel (robot_sim's GROUND_TRUTH); when set, the fixes'
  /// errors against it are printed (fix_truth_check.hpp) before the calibration.
  std::string truth_channel;
  std::optional<Pose2> true_robot_T_laser;  ///< the simulated robot's mount (default: the one read with)
  /// Windows up to 5 s: on the simulated calibration drive 1 s windows gave scales 0.5 % high
  /// (end-of-window timing), 2..10 s windows agreed within 0.05 %.
  WindowOptions windows = [] {
    WindowOptions w;
    w.max_duration_s = 5.0;
    return w;
  }();
};

/// Returns the exit code: 0 solved, 1 the drive does not determine the scales, 2 bad input.
int run_odometry_calibration(const OdometryCommandOptions& o);

}  // namespace refloc
