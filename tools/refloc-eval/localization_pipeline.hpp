#pragma once
// Extractor, matcher and solver called directly on one scan, in one of the two
// modes: what the three services do over LCM, without LCM, for accuracy studies.

#include "common/laser_scan.hpp"
#include "common/reflector_map.hpp"
#include "pose_solver/pose_solver.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_matcher/reflector_matcher.hpp"

#include <memory>
#include <string>

namespace refloc {

enum class PipelineMode { kPaper, kDefault };
const char* to_string(PipelineMode mode);

struct PipelineOutput {
  const std::vector<ReflectorDetection>* detections = nullptr;
  MatchResult match;
  PoseSolution solution;
  /// The pose the pipeline would publish as OK: matcher OK and solver OK or DEGRADED.
  bool published_ok() const;
};

/// The three libraries' settings for one mode.
struct PipelineConfigs {
  ExtractorConfig extractor;
  MatcherConfig matcher;
  SolverConfig solver;
};

/// Each mode's settings read from the services' own config files (the deployed
/// configuration, so a study measures what runs), with "mode" forced to mode.
PipelineConfigs load_pipeline_configs(PipelineMode mode, const std::string& extractor_file,
                                      const std::string& matcher_file, const std::string& solver_file);

class LocalizationPipeline {
 public:
  LocalizationPipeline(PipelineMode mode, const PipelineConfigs& configs, const ReflectorMap& map,
                       const Pose2& robot_T_laser);
  /// Localize from one scan; with prior (map_T_robot) the default mode tracks, else relocalizes.
  const PipelineOutput& run(const LaserScan& scan, const Pose2* prior_map_T_robot = nullptr);
  PipelineMode mode() const { return mode_; }

 private:
  PipelineMode mode_;
  Pose2 robot_T_laser_;
  ReflectorExtractor extractor_;
  ReflectorMatcher matcher_;
  PoseSolver solver_;
  PipelineOutput output_;
};

}  // namespace refloc
