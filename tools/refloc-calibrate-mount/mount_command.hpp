#pragma once
// refloc-calibrate-mount's work: read the drive from a log, solve the mount, print it and the
// robot.json snippet (and optionally write them as JSON).

#include "calibration_log.hpp"

#include <string>

namespace refloc {

struct MountCommandOptions {
  std::string log_path;
  std::string robot_path = "deploy/config/robot.json";  ///< the robot file the services ran with
  std::string json_path;                                ///< also write the result here
  CalibrationChannels channels;
  WindowOptions windows;
  bool estimate_translation_scale = true;
  std::string method = "direct";  ///< "direct" (mount_direct.hpp, every fix) or "hand-eye" (windows)
  double segment_s = 4.0;         ///< direct: segment length [s]
};

/// Returns the exit code: 0 solved, 1 the drive does not determine the mount, 2 bad input.
int run_mount_calibration(const MountCommandOptions& o);

}  // namespace refloc
