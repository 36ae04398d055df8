#pragma once
// Reads a survey drive from an LCM log into DriveScans: the one place the driving survey
// decodes lcmtypes. Scans and odometry go to DriveScanBuilder in log order, the order in
// which the reflector_extractor service would have received them.

#include "calibration_pairs.hpp"
#include "drive_scan.hpp"

#include <cstdint>
#include <string>

namespace refloc {

struct DriveLogCounts {
  int64_t events = 0;       ///< events in the log
  int64_t undecodable = 0;  ///< scan or odometry events refused by the bounded decode
};

/// Channels are the extractor config's input_channel (scans) and odometry_channel.
/// Throws ConfigError when the file is not an LCM log.
std::vector<DriveScan> read_drive_log(const std::string& path, const ExtractorServiceConfig& extractor,
                                      const Pose2& robot_T_laser, const DriveScanOptions& options,
                                      DriveScanCounts& scan_counts, DriveLogCounts& log_counts);

/// Simulation: the true map_T_robot series of channel (pose2d_t, GROUND_TRUTH), sorted by utime.
std::vector<TimedPose> read_true_poses(const std::string& path, const std::string& channel);

}  // namespace refloc
