#pragma once
// pose_fusion's config file (deploy/config/pose_fusion.json). Every key is
// optional with the default of the struct it fills; the sections mirror the
// structs: "fusion" is FusionConfig, "continuity" OdometryContinuityConfig. The
// odometry noise is the robot's (robot.json), not read here.

#include "pose_fusion/odometry_continuity.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <string>

namespace refloc {

class JsonConfig;

/// What the filter corrects odometry with.
enum class FusionMeasurements {
  kDetections,  ///< REFLECTOR_MATCHES' detections; LASER_POSE only (re-)initialises
  kLaserPose,   ///< LASER_POSE fixes (the single-scan summary), REFLECTOR_MATCHES not read
};

struct FusionServiceConfig {
  FusionConfig fusion;
  FusionMeasurements measurements = FusionMeasurements::kDetections;
  /// Share of robot.json's odometry variance the filter treats as random while it
  /// estimates the odometry's calibration error (the rest is that error).
  double odometry_random_noise_fraction = 0.025;
  /// When consecutive ODOMETRY messages are not one continuous frame.
  OdometryContinuityConfig continuity;
  /// No ODOMETRY this long: fixes are published as DEGRADED POSE (OdometrySilence) [s].
  double odometry_timeout = 0.1;
  std::string odometry_channel = "ODOMETRY";
  std::string fix_channel = "LASER_POSE";
  std::string matches_channel = "REFLECTOR_MATCHES";
  std::string output_channel = "POSE";
};

/// The whole file; call config.reject_unknown_keys() afterwards.
FusionServiceConfig parse_fusion_service_config(const JsonConfig& config);

/// Load, parse and reject unknown keys; "" gives the defaults.
FusionServiceConfig load_fusion_service_config(const std::string& path);

}  // namespace refloc
