#include "eval_command.hpp"

#include "accuracy_study.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "eval_plot.hpp"
#include "eval_report.hpp"
#include "study_map.hpp"
#include "world_renderer/world_loader.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>

namespace refloc {

namespace {

sim::Lms100ErrorModel sensor_model(const EvalOptions& o) {
  if (o.range_walk_rssi_bright <= o.range_walk_rssi_weak) {
    throw ConfigError(fmt::format("--range-walk-rssi-bright {} must be above --range-walk-rssi-weak {}",
                                  o.range_walk_rssi_bright, o.range_walk_rssi_weak));
  }
  sim::Lms100ErrorModel m;
  m.range_sigma = o.sigma_mm / 1000.0;
  m.range_offset = o.offset_mm / 1000.0;
  m.range_scale_ppm = o.range_scale_ppm;
  m.range_walk_bright = o.range_walk_mm / 1000.0;
  m.range_walk_weak = o.range_walk_weak_mm / 1000.0;
  m.range_walk_rssi_weak = o.range_walk_rssi_weak;
  m.range_walk_rssi_bright = o.range_walk_rssi_bright;
  m.retro_range_bias = o.retro_range_bias_mm / 1000.0;
  m.rssi_scale = o.rssi_scale == "8bit_in_16bit" ? sim::RssiScale::k8BitIn16Bit : sim::RssiScale::k16Bit;
  return m;
}

}  // namespace

int run_eval(const std::string& command, EvalOptions o) {
  const bool paper_table = command == "paper-table";
  if (o.world_file.empty())
    o.world_file =
        shipped_path(paper_table ? "deploy/config/paper_cell.json" : "deploy/config/world_demo.json");
  if (o.out_prefix.empty()) {
    o.out_prefix = !o.json_file.empty() && o.json_file.size() > 5 &&
                           o.json_file.compare(o.json_file.size() - 5, 5, ".json") == 0
                       ? o.json_file.substr(0, o.json_file.size() - 5)
                       : "logs/refloc-eval-" + command;
  }
  const sim::World world = sim::load_world(o.world_file);
  const ReflectorMap map = study_map(world, o.map_file, o.occluders);
  const RobotConfig robot = load_robot_config(o.robot_file);
  StudyConfig config;
  config.sensor = sensor_model(o);
  config.seed = o.seed;
  config.repeats = paper_table ? o.repeats : 1;
  config.scan_spacing = o.scan_spacing_s;
  std::mt19937_64 pose_rng(o.seed + 1000);
  const std::vector<Pose2> poses =
      paper_table ? paper_table_poses() : random_drivable_poses(world, o.n, 0.4, pose_rng);
  if (poses.empty())
    throw ConfigError(o.world_file + ": /drivable_areas: no pose could be drawn (missing or too small)");
  PipelineConfigs paper_configs =
      load_pipeline_configs(PipelineMode::kPaper, o.extractor_file, o.matcher_file, o.solver_file);
  PipelineConfigs default_configs =
      load_pipeline_configs(PipelineMode::kDefault, o.extractor_file, o.matcher_file, o.solver_file);
  // The clustering threshold and the fit weights follow the simulated sensor's noise.
  paper_configs.extractor.extractor.clustering.range_sigma = config.sensor.range_sigma;
  default_configs.extractor.extractor.clustering.range_sigma = config.sensor.range_sigma;
  const StudyResult r = run_study(world, map, robot.robot_T_laser, paper_configs, default_configs, poses,
                                  config, o.progress ? ProgressCallback(print_progress) : ProgressCallback());
  if (paper_table) print_paper_table(r, poses, config.repeats);
  fmt::print("\n{} over {} poses x {} scans, world {}\n{}\noccluders in the map: {} ({} segments)\n", command,
             poses.size(), config.repeats, o.world_file, describe(config.sensor), o.occluders,
             occluder_segment_count(map.occluders));
  print_summary("paper", r.paper);
  print_summary("default", r.default_mode);

  nlohmann::json j;
  j["command"] = command;
  j["world"] = o.world_file;
  j["map"] = o.map_file.empty() ? world.map_file : o.map_file;
  j["occluders"] = o.occluders;
  j["occluder_segments"] = occluder_segment_count(map.occluders);
  j["sigma_mm"] = o.sigma_mm;
  j["offset_mm"] = o.offset_mm;
  j["sensor_model"] = to_json(config.sensor);
  j["seed"] = o.seed;
  j["scans_per_pose"] = config.repeats;
  j["modes"]["paper"] = to_json(r.paper);
  j["modes"]["default"] = to_json(r.default_mode);
  if (paper_table) j["paper_reported"] = {{"mean_max_err_x_mm", 14.3}, {"mean_max_err_y_mm", 14.7}};
  if (!o.json_file.empty()) std::ofstream(o.json_file) << j.dump(2) << "\n";
  std::ofstream(o.out_prefix + ".csv") << measurements_csv(r.measurements);
  std::vector<std::string> plot = {
      "eval",
      "--csv",
      o.out_prefix + ".csv",
      "--world",
      o.world_file,
      "--out",
      o.out_prefix + ".png",
      "--out",
      o.out_prefix + ".svg",
      "--title",
      fmt::format("refloc-eval {} ({} poses x {} scans, world {})", command, poses.size(), config.repeats,
                  std::filesystem::path(o.world_file).filename().string())};
  if (paper_table) {
    std::ofstream(o.out_prefix + ".paper.csv") << paper_reported_errors_csv();
    plot.insert(plot.end(), {"--reference", o.out_prefix + ".paper.csv"});
  }
  fmt::print("wrote {}.csv{}\n", o.out_prefix, o.json_file.empty() ? "" : " and " + o.json_file);
  // The numbers are the result; a missing matplotlib costs only the picture.
  if (run_refloc_plot(plot) != 0)
    fmt::print(stderr, "refloc-eval: no picture (tools/refloc-plot needs python3 and python3-matplotlib)\n");
  return 0;
}

}  // namespace refloc
