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

class LocalizationPipeline {
 public:
  LocalizationPipeline(PipelineMode mode, const ReflectorMap& map, const Pose2& robot_T_laser, double range_sigma);
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
