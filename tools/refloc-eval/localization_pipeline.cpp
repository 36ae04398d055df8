#include "localization_pipeline.hpp"

#include "common/json_config.hpp"

namespace refloc {
namespace {

/// The file's document with "/mode" set, so one file yields both modes' settings.
JsonConfig with_mode(const std::string& path, PipelineMode mode) {
  const JsonConfig file = JsonConfig::load_file(path);
  nlohmann::json document = file.document();
  document["mode"] = to_string(mode);
  return JsonConfig(std::move(document), path);
}

MatchVerdict verdict_of(MatchStatus s) {
  switch (s) {
    case MatchStatus::kOk:
      return MatchVerdict::kOk;
    case MatchStatus::kAmbiguous:
      return MatchVerdict::kAmbiguous;
    case MatchStatus::kLost:
      break;
  }
  return MatchVerdict::kLost;
}

}  // namespace

const char* to_string(PipelineMode mode) { return mode == PipelineMode::kPaper ? "paper" : "default"; }

PipelineConfigs load_pipeline_configs(PipelineMode mode, const std::string& extractor_file,
                                      const std::string& matcher_file, const std::string& solver_file) {
  PipelineConfigs configs;
  const JsonConfig extractor = with_mode(extractor_file, mode);
  configs.extractor = parse_extractor_service_config(extractor);
  extractor.reject_unknown_keys();
  const JsonConfig matcher = with_mode(matcher_file, mode);
  configs.matcher = parse_matcher_service_config(matcher, ".");
  matcher.reject_unknown_keys();
  const JsonConfig solver = with_mode(solver_file, mode);
  configs.solver = parse_solver_service_config(solver);
  solver.reject_unknown_keys();
  return configs;
}

PipelineConfigs load_deployed_pipeline_configs(const std::string& config_dir) {
  PipelineConfigs configs;
  const JsonConfig extractor = JsonConfig::load_file(config_dir + "/reflector_extractor.json");
  configs.extractor = parse_extractor_service_config(extractor);
  extractor.reject_unknown_keys();
  configs.matcher = load_matcher_service_config(config_dir + "/reflector_matcher.json");
  const JsonConfig solver = JsonConfig::load_file(config_dir + "/pose_solver.json");
  configs.solver = parse_solver_service_config(solver);
  solver.reject_unknown_keys();
  return configs;
}

LocalizationPipeline::LocalizationPipeline(PipelineMode mode, const PipelineConfigs& configs,
                                           const ReflectorMap& map, const Pose2& robot_T_laser)
    : mode_(mode),
      extractor_(configs.extractor, robot_T_laser),
      matcher_(map, configs.matcher, robot_T_laser),
      solver_(configs.solver.solver, robot_T_laser) {}

const PipelineOutput& LocalizationPipeline::on_scan(const LaserScan& scan) {
  const ExtractorOutput& extraction = extractor_.on_scan(scan);
  const MatcherOutput& match = matcher_.on_detections(extraction.utime, extraction.detections);
  output_.extraction = &extraction;
  output_.match = &match;
  output_.fix = &solver_.on_scan_matches(match.utime, verdict_of(match.result.status), extraction.detections,
                                         match.result.matches);
  output_.solution = &solver_.solution();
  return output_;
}

}  // namespace refloc
