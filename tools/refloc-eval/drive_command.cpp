#include "drive_command.hpp"

#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "drive_study.hpp"
#include "eval_plot.hpp"
#include "path_plot_trace.hpp"
#include "study_map.hpp"
#include "world_renderer/world_loader.hpp"

#include <fmt/format.h>

#include <fstream>
#include <vector>

namespace refloc {

int run_drive_command(const DriveOptions& o) {
  const sim::World world = sim::load_world(o.world_file);
  const ReflectorMap map = study_map(world, o.map_file, o.occluders);
  const RobotConfig robot = load_robot_config(o.robot_file);
  PipelineConfigs configs =
      load_pipeline_configs(PipelineMode::kDefault, o.extractor_file, o.matcher_file, o.solver_file);
  DriveConfig config;
  config.sensor.range_sigma = o.sigma_mm / 1000.0;
  config.seed = o.seed;
  config.warmup_s = o.warmup_s;
  // The clustering threshold and the fit weights follow the simulated sensor's noise.
  configs.extractor.extractor.clustering.range_sigma = config.sensor.range_sigma;
  if (o.fix_window_s > 0.0) configs.extractor.fix_velocity.window_s = o.fix_window_s;
  const DrivePath path = DrivePath::demo_hall_loop(
      o.speed_mps, o.heading == "fixed" ? DrivePath::Heading::kFixed : DrivePath::Heading::kTangent);
  config.duration_s = o.duration_s > 0.0 ? o.duration_s : path.lap_length() / o.speed_mps;

  std::vector<DriveMotionSource> sources;
  if (o.odometry_only) sources.push_back(DriveMotionSource::kOdometry);
  if (o.no_odometry_only) sources.push_back(DriveMotionSource::kNoOdometry);
  if (o.no_compensation_only) sources.push_back(DriveMotionSource::kNoCompensation);
  if (sources.empty())
    sources = {DriveMotionSource::kOdometry, DriveMotionSource::kNoOdometry,
               DriveMotionSource::kNoCompensation};

  fmt::print(
      "drive: {:.1f} s at {:.2f} m/s around the {:.1f} m loop of {} (heading {}), scored after {:.1f} s; "
      "range sigma {:.1f} mm, seed {}; fix_velocity window {:.2f} s\n",
      config.duration_s, o.speed_mps, path.lap_length(), o.world_file, o.heading, config.warmup_s, o.sigma_mm,
      o.seed, configs.extractor.fix_velocity.window_s);
  fmt::print("occluders in the map: {} ({} segments)\n", o.occluders, occluder_segment_count(map.occluders));
  fmt::print(
      "{:<16} {:>5} {:>5} {:>4} {:>5} | {:>6} {:>6} {:>5} | {:>7} {:>6} {:>7} {:>6} {:>6} | {:>5} {:>6} "
      "{:>5}\n",
      "source", "scans", "OK", "DEG", "wrong", "odo", "fixes", "none", "along", "rms", "cross", "rms", "RMSE",
      "NEES", ">99%", "hNEES");
  nlohmann::json j;
  j["command"] = "drive";
  j["world"] = o.world_file;
  j["map"] = o.map_file.empty() ? world.map_file : o.map_file;
  j["occluders"] = o.occluders;
  j["occluder_segments"] = occluder_segment_count(map.occluders);
  j["speed_mps"] = o.speed_mps;
  j["duration_s"] = config.duration_s;
  j["warmup_s"] = config.warmup_s;
  j["heading"] = o.heading;
  j["sigma_mm"] = o.sigma_mm;
  j["seed"] = o.seed;
  j["fix_velocity_window_s"] = configs.extractor.fix_velocity.window_s;
  // The picture's data next to the JSON (as paper-table / random write theirs).
  const bool json_named =
      o.json_file.size() > 5 && o.json_file.compare(o.json_file.size() - 5, 5, ".json") == 0;
  const std::string prefix =
      json_named ? o.json_file.substr(0, o.json_file.size() - 5) : "logs/refloc-eval-drive";
  std::vector<std::string> plot = {"drive",
                                   "--world",
                                   o.world_file,
                                   "--out",
                                   prefix + ".png",
                                   "--out",
                                   prefix + ".svg",
                                   "--title",
                                   fmt::format("refloc-eval drive: {:.0f} s at {:.2f} m/s, heading {}",
                                               config.duration_s, o.speed_mps, o.heading)};
  int traces_written = 0;
  for (DriveMotionSource source : sources) {
    const DriveSummary s = run_drive(world, map, robot.robot_T_laser, configs, path, source, config);
    fmt::print(
        "{:<16} {:>5} {:>5} {:>4} {:>5} | {:>6} {:>6} {:>5} | {:>+7.2f} {:>6.2f} {:>+7.2f} {:>6.2f} {:>6.2f} "
        "| "
        "{:>5.2f} {:>5.1f}% {:>5.2f}\n",
        to_string(source), s.scored_scans, s.ok_fixes, s.degraded_fixes, s.wrong_fixes,
        s.compensated_odometry, s.compensated_fixes, s.not_compensated, s.along_mean_mm, s.along_rms_mm,
        s.cross_mean_mm, s.cross_rms_mm, s.position_rmse_mm, s.consistency.position_nees_mean,
        100.0 * s.consistency.position_outside_99, s.consistency.heading_nees_mean);
    j["runs"][to_string(source)] = to_json(s);
    const std::string trace_file = fmt::format("{}.{}.trace.csv", prefix, to_string(source));
    if (write_path_trace_csv(trace_file, s.trace)) {
      plot.insert(plot.end(), {"--trace", fmt::format("{}={}", to_string(source), trace_file)});
      ++traces_written;
    }
  }
  fmt::print(
      "(scans: scored scans; odo/fixes/none: the extractor's motion source; along/cross: mean error along / "
      "left of the direction of travel [mm], + along = ahead of the truth at the fix's stamp; NEES: "
      "position, "
      "2 when honest, >99%: share outside the 99 % ellipse; hNEES: heading, 1 when honest)\n");
  if (!o.json_file.empty()) {
    std::ofstream(o.json_file) << j.dump(2) << "\n";
    fmt::print("wrote {}\n", o.json_file);
  }
  // The numbers are the result; a missing matplotlib or folder costs only the picture.
  if (traces_written == 0)
    fmt::print(stderr, "refloc-eval: cannot write {}.*.trace.csv: no picture\n", prefix);
  else if (run_refloc_plot(plot) != 0)
    fmt::print(stderr,
               "refloc-eval: no picture (tools/refloc-plot needs /usr/bin/python3 and python3-matplotlib)\n");
  return 0;
}

}  // namespace refloc
