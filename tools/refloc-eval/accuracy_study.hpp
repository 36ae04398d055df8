#pragma once
// Accuracy studies in simulation: render LMS100 scans of a world from known
// robot poses with the sensor error model, localize each scan with both
// pipeline modes, and compare with the truth and the Cramér-Rao bound.

#include "common/se2.hpp"
#include "fix_consistency.hpp"
#include "localization_pipeline.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world.hpp"

#include <nlohmann/json.hpp>

#include <functional>
#include <random>
#include <string>
#include <vector>

namespace refloc {

struct StudyConfig {
  /// The simulated sensor: its range_sigma also sizes the Cramér-Rao bound.
  sim::Lms100ErrorModel sensor;
  int repeats = 1;  ///< scans per pose
  uint64_t seed = 1;
  double wrong_distance = 0.2;  ///< a published pose farther than this from the truth is wrong [m]
  double wrong_angle = 5.0 * M_PI / 180.0;  ///< ... or turned more than this [rad]
  double detection_match_distance = 0.1;    ///< a detection this close to a real reflector is true [m]
  /// Time between consecutive scans [s]. Poses are independent trials: with more than the
  /// matcher's prior_max_age_s between scans neither a POSE nor its own last fix is fresh,
  /// so the services' prior rule (PriorSelector) gives no prior and every scan is a global
  /// relocalization, as on a robot that just woke up there.
  double scan_spacing = 1.0;
};

struct Measurement {
  PipelineMode mode = PipelineMode::kDefault;
  int pose_index = 0;
  int repeat = 0;
  Pose2 truth;
  bool published_ok = false;
  MatchStatus match_status = MatchStatus::kLost;
  SolveStatus solve_status = SolveStatus::kLost;
  Pose2 estimate;
  int reflectors_used = 0;
  bool has_crlb = false;
  double crlb_var_xy = 0.0;  ///< trace of the position block of the bound, LMS100 spot [m^2]
  bool has_point_beam_crlb = false;
  double point_beam_crlb_var_xy = 0.0;  ///< the same for ideal point beams [m^2]
  int visible_reflectors = 0;
  int detected_visible = 0;
  int detections = 0;
  int false_detections = 0;
  bool wrong = false;  ///< published as OK but off by more than the wrong-pose limits
  /// The matcher said OK and paired a detection with a reflector more than wrong_distance from
  /// where the detection really is (judged on the matches, whatever the solver made of them).
  bool match_wrong = false;
  bool fix_ok = false;                                   ///< the fix's status is OK (not DEGRADED)
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< the published one [m^2, m rad, rad^2]
};

struct ModeSummary {
  int poses = 0;
  int measurements = 0;
  int published_ok = 0;
  int wrong_matches = 0;
  int match_ok = 0;                ///< scans the matcher answered OK
  int match_ok_wrong = 0;          ///< of them, with a wrong pair (Measurement::match_wrong)
  double mean_max_err_x_mm = 0.0;  ///< mean over poses of the max |dx| over its repeats
  double mean_max_err_y_mm = 0.0;
  double rmse_mm = 0.0;  ///< sqrt(mean(dx^2 + dy^2)) over published, not wrong, measurements
  double max_err_mm = 0.0;
  double heading_rmse_deg = 0.0;
  double crlb_rmse_mm = 0.0;             ///< sqrt(mean(trace of the bound's position block))
  double crlb_ratio = 0.0;               ///< rmse / crlb_rmse
  double point_beam_crlb_rmse_mm = 0.0;  ///< the bound if the beams were ideal points
  double point_beam_crlb_ratio = 0.0;    ///< rmse / point_beam_crlb_rmse
  double recall = 0.0;                   ///< visible reflectors detected / visible reflectors
  double false_detection_rate = 0.0;     ///< detections not on a real reflector / detections
  /// NEES of the OK, not wrong, fixes against their published covariance (fix_consistency.hpp).
  ConsistencySummary consistency;
};

struct StudyResult {
  std::vector<Measurement> measurements;
  ModeSummary paper;
  ModeSummary default_mode;
};

/// The 10 robot positions of the paper's Table 1 [m], heading 0.
std::vector<Pose2> paper_table_poses();

/// n poses uniform over the world's drivable areas with uniform heading, at least
/// clearance [m] from any wall, obstacle or reflector.
std::vector<Pose2> random_drivable_poses(const sim::World& world, int n, double clearance,
                                         std::mt19937_64& rng);

using ProgressCallback = std::function<void(size_t done, size_t total)>;

/// Render every pose config.repeats times and localize each scan in both modes.
StudyResult run_study(const sim::World& world, const ReflectorMap& map, const Pose2& robot_T_laser,
                      const PipelineConfigs& paper_configs, const PipelineConfigs& default_configs,
                      const std::vector<Pose2>& poses, const StudyConfig& config,
                      const ProgressCallback& progress);

nlohmann::json to_json(const ModeSummary& summary);
/// One CSV row per measurement, with a header.
std::string measurements_csv(const std::vector<Measurement>& measurements);

}  // namespace refloc
