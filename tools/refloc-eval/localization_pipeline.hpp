#pragma once
// The three services' nodes (ExtractorNode, MatcherNode, SolverNode) chained without LCM,
// fed message by message in time order (odometry, fused poses, scans) exactly as the
// services are: the same configs, the same prior rule (PriorSelector), the same LASER_POSE
// rule (make_laser_fix). Accuracy studies feed rendered scans; a log replays through it.

#include "common/laser_scan.hpp"
#include "common/reflector_map.hpp"
#include "pose_solver/solver_config_file.hpp"
#include "pose_solver/solver_node.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_node.hpp"
#include "reflector_matcher/matcher_config_file.hpp"
#include "reflector_matcher/matcher_node.hpp"

#include <string>

namespace refloc {

enum class PipelineMode { kPaper, kDefault };
const char* to_string(PipelineMode mode);

struct PipelineOutput {
  const ExtractorOutput* extraction = nullptr;
  const MatcherOutput* match = nullptr;
  const LaserFix* fix = nullptr;
  const PoseSolution* solution = nullptr;  ///< the solver's, stale when the matcher was not OK

  const std::vector<ReflectorDetection>& detections() const { return extraction->detections; }
  /// The LASER_POSE the services would publish carries a pose (OK or DEGRADED).
  bool published_ok() const { return fix->has_pose; }
};

/// The three services' settings, as their config files give them.
struct PipelineConfigs {
  ExtractorServiceConfig extractor;
  MatcherServiceConfig matcher;
  SolverServiceConfig solver;
};

/// Each mode's settings read from the services' own config files (the deployed
/// configuration, so a study measures what runs), with "mode" forced to mode.
PipelineConfigs load_pipeline_configs(PipelineMode mode, const std::string& extractor_file,
                                      const std::string& matcher_file, const std::string& solver_file);

/// The services' configs as deployed (deploy/config/ under source_dir), mode as in the files.
PipelineConfigs load_deployed_pipeline_configs(const std::string& config_dir);

class LocalizationPipeline {
 public:
  LocalizationPipeline(PipelineMode mode, const PipelineConfigs& configs, const ReflectorMap& map,
                       const Pose2& robot_T_laser);

  /// ODOMETRY: the extractor's motion compensation uses the latest.
  void on_odometry(const OdometrySample& sample) { extractor_.on_odometry(sample); }
  /// LASER_POSE fed back: the extractor's motion source while ODOMETRY is absent or stale.
  void on_laser_pose(const LaserPoseFix& fix) { extractor_.on_laser_pose(fix); }
  /// POSE: the matcher's prior candidate (PriorSelector decides per scan).
  void on_pose(const FusedPose& pose) { matcher_.on_pose(pose); }
  /// LMS100_SCAN: extract, match, solve; the reference stays valid until the next call.
  const PipelineOutput& on_scan(const LaserScan& scan);

  PipelineMode mode() const { return mode_; }

 private:
  PipelineMode mode_;
  ExtractorNode extractor_;
  MatcherNode matcher_;
  SolverNode solver_;
  PipelineOutput output_;
};

}  // namespace refloc
