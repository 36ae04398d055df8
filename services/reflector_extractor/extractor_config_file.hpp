#pragma once
// deploy/config/reflector_extractor.json: the extractor's parameters and the service's
// channels. Every key is optional (defaults from ExtractorConfig, or from
// ExtractorConfig::paper() when "mode" is "paper"); values are range-checked.

#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/fix_velocity_estimator.hpp"
#include "reflector_extractor/rssi_scale.hpp"

#include <string>

namespace refloc {

class JsonConfig;

struct ExtractorServiceConfig {
  ExtractorConfig extractor;
  std::string input_channel = "LMS100_SCAN";
  std::string output_channel = "REFLECTORS";
  /// Every bright cluster with its outcome and the threshold, per scan; "" publishes none.
  std::string clusters_channel = "REFLECTOR_CLUSTERS";
  std::string odometry_channel = "ODOMETRY";
  /// The solver's fixes, the motion source while ODOMETRY is absent or stale.
  std::string laser_pose_channel = "LASER_POSE";
  bool motion_compensation = true;
  /// Odometry older than this (by message utime, relative to the scan) is not used [s].
  double odometry_max_age = 0.2;
  /// The twist fitted to recent LASER_POSE fixes ("fix_velocity": {...}).
  FixVelocityConfig fix_velocity;
  /// How a 16-bit RSSI channel is read ("rssi_scale": auto / native / 8bit_in_16bit).
  RssiScaleConfig rssi_scale;
  /// Accepted scans without any reflector for longer than this degrade the state [s].
  double no_reflector_timeout = 2.0;
};

/// Read the service config from a loaded document (the caller rejects unknown keys).
ExtractorServiceConfig parse_extractor_service_config(const JsonConfig& config);
/// Load, read and reject unknown keys; the defaults when path is empty.
ExtractorServiceConfig load_extractor_service_config(const std::string& path);

}  // namespace refloc
