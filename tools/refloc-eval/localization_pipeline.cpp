#include "localization_pipeline.hpp"

namespace refloc {
namespace {

ExtractorConfig extractor_config(PipelineMode mode, double range_sigma) {
  ExtractorConfig c = mode == PipelineMode::kPaper ? ExtractorConfig::paper() : ExtractorConfig{};
  c.clustering.range_sigma = range_sigma;
  return c;
}

MatcherConfig matcher_config(PipelineMode mode) {
  MatcherConfig c;
  c.mode = mode == PipelineMode::kPaper ? MatcherMode::kPaper : MatcherMode::kDefault;
  return c;
}

SolverConfig solver_config(PipelineMode mode) {
  SolverConfig c;
  c.mode = mode == PipelineMode::kPaper ? SolverMode::kPaper : SolverMode::kDefault;
  return c;
}

}  // namespace

const char* to_string(PipelineMode mode) { return mode == PipelineMode::kPaper ? "paper" : "default"; }

bool PipelineOutput::published_ok() const {
  return match.status == MatchStatus::kOk &&
         (solution.status == SolveStatus::kOk || solution.status == SolveStatus::kDegraded);
}

LocalizationPipeline::LocalizationPipeline(PipelineMode mode, const ReflectorMap& map, const Pose2& robot_T_laser,
                                           double range_sigma)
    : mode_(mode),
      robot_T_laser_(robot_T_laser),
      extractor_(extractor_config(mode, range_sigma)),
      matcher_(map, matcher_config(mode)),
      solver_(solver_config(mode), robot_T_laser) {}

const PipelineOutput& LocalizationPipeline::run(const LaserScan& scan, const Pose2* prior_map_T_robot) {
  output_.detections = &extractor_.extract(scan);
  PosePrior prior;
  const PosePrior* prior_ptr = nullptr;
  if (prior_map_T_robot && mode_ == PipelineMode::kDefault) {
    prior.map_T_laser = *prior_map_T_robot * robot_T_laser_;
    prior.covariance = Eigen::Vector3d(0.02 * 0.02, 0.02 * 0.02, 0.01 * 0.01).asDiagonal();
    prior_ptr = &prior;
  }
  matcher_.match(*output_.detections, prior_ptr, output_.match);
  solver_.solve(*output_.detections, output_.match.matches, output_.solution);
  return output_;
}

}  // namespace refloc
