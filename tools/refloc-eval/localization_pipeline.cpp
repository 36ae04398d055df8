#include "localization_pipeline.hpp"

#include "common/json_config.hpp"
#include "pose_solver/solver_config_file.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_matcher/matcher_config_file.hpp"

namespace refloc {
namespace {

/// The file's document with "/mode" set, so one file yields both modes' settings.
JsonConfig with_mode(const std::string& path, PipelineMode mode) {
  const JsonConfig file = JsonConfig::load_file(path);
  nlohmann::json document = file.document();
  document["mode"] = to_string(mode);
  return JsonConfig(std::move(document), path);
}

}  // namespace

const char* to_string(PipelineMode mode) { return mode == PipelineMode::kPaper ? "paper" : "default"; }

bool PipelineOutput::published_ok() const {
  return match.status == MatchStatus::kOk &&
         (solution.status == SolveStatus::kOk || solution.status == SolveStatus::kDegraded);
}

PipelineConfigs load_pipeline_configs(PipelineMode mode, const std::string& extractor_file,
                                      const std::string& matcher_file, const std::string& solver_file) {
  PipelineConfigs configs;
  const JsonConfig extractor = with_mode(extractor_file, mode);
  configs.extractor = parse_extractor_service_config(extractor).extractor;
  extractor.reject_unknown_keys();
  const JsonConfig matcher = with_mode(matcher_file, mode);
  configs.matcher = parse_matcher_service_config(matcher, ".").matcher;
  matcher.reject_unknown_keys();
  const JsonConfig solver = with_mode(solver_file, mode);
  configs.solver = parse_solver_service_config(solver).solver;
  solver.reject_unknown_keys();
  return configs;
}

LocalizationPipeline::LocalizationPipeline(PipelineMode mode, const PipelineConfigs& configs,
                                           const ReflectorMap& map, const Pose2& robot_T_laser)
    : mode_(mode),
      robot_T_laser_(robot_T_laser),
      extractor_(configs.extractor),
      matcher_(map, configs.matcher),
      solver_(configs.solver, robot_T_laser) {}

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
