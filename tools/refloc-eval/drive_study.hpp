#pragma once
// refloc-eval drive: consecutive scans of a moving robot (every beam rendered from the
// laser's true pose at its own time), localized by the services' nodes in time order with
// each LASER_POSE fed back to the extractor as the service gets it over LCM; every OK fix
// compared with the true pose at its stamp. What motion compensation buys, with odometry,
// with the fixes' own twist (no odometry) and with none.

#include "drive_path.hpp"
#include "fix_consistency.hpp"
#include "localization_pipeline.hpp"
#include "path_plot_trace.hpp"
#include "world_renderer/lms100_error_model.hpp"
#include "world_renderer/world.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace refloc {

/// Which motion source the extractor gets.
enum class DriveMotionSource {
  kOdometry,        ///< ODOMETRY at 100 Hz (true twist) and LASER_POSE: the stack as deployed
  kNoOdometry,      ///< LASER_POSE only: the fixes' twist
  kNoCompensation,  ///< motion_compensation false
};
const char* to_string(DriveMotionSource source);

struct DriveConfig {
  sim::Lms100ErrorModel sensor;
  double duration_s = 60.0;         ///< simulated time [s]
  double warmup_s = 2.0;            ///< fixes before this are not scored (matcher cold start) [s]
  double scan_period_s = 0.02;      ///< LMS100 at 50 Hz [s]
  double odometry_period_s = 0.01;  ///< mecanum_odometry's rate from robot_sim [s]
  double wrong_distance = 0.2;      ///< an OK fix farther than this from the truth is wrong, not scored [m]
  uint64_t seed = 1;
};

struct DriveSummary {
  DriveMotionSource source = DriveMotionSource::kOdometry;
  int scans = 0;
  int scored_scans = 0;  ///< after the warm-up
  int ok_fixes = 0;      ///< scored OK fixes (the statistics below are over them)
  int degraded_fixes = 0;
  int fixes_without_pose = 0;
  int wrong_fixes = 0;           ///< OK but more than wrong_distance off: left out of the statistics
  int compensated_odometry = 0;  ///< scored scans by the extractor's motion source
  int compensated_fixes = 0;
  int not_compensated = 0;
  double along_mean_mm = 0.0;  ///< error along the direction of travel, + = ahead of the truth
  double along_rms_mm = 0.0;
  double cross_mean_mm = 0.0;  ///< error across it, + = left of the track
  double cross_rms_mm = 0.0;
  double position_rmse_mm = 0.0;
  double heading_mean_mdeg = 0.0;  ///< estimate - truth [millidegrees]
  double heading_rms_mdeg = 0.0;
  ConsistencySummary consistency;  ///< NEES of the scored OK fixes
  /// For the picture: the true pose at every scan (GROUND_TRUTH) and the scored OK fixes that
  /// are not wrong (LASER_POSE, with their error against the truth at their stamp); t = 0 at the start.
  PathTrace trace;
};

/// Drive path for config.duration_s through world, one run with source.
DriveSummary run_drive(const sim::World& world, const ReflectorMap& map, const Pose2& robot_T_laser,
                       PipelineConfigs configs, const DrivePath& path, DriveMotionSource source,
                       const DriveConfig& config);

nlohmann::json to_json(const DriveSummary& summary);

}  // namespace refloc
