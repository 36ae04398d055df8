// refloc-eval: accuracy studies of the localization pipeline in simulation.
//   refloc-eval paper-table   the paper's Table 1 protocol, both modes side by side
//   refloc-eval random --n N  random poses of a world; also wrong matches, recall, false detections

#include "accuracy_study.hpp"
#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "path_plot_svg.hpp"
#include "world_renderer/world_loader.hpp"

#include <fmt/format.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace refloc {
namespace {

struct Options {
  std::string world_file;
  std::string robot_file = "deploy/config/robot.json";
  std::string extractor_file = "deploy/config/reflector_extractor.json";
  std::string matcher_file = "deploy/config/reflector_matcher.json";
  std::string solver_file = "deploy/config/pose_solver.json";
  double sigma_mm = 12.0;
  double offset_mm = 0.0;
  uint64_t seed = 1;
  int repeats = 3;
  int n = 1000;
  std::string json_file;
  std::string out_prefix;
  bool progress = isatty(2) != 0;
};

void print_progress(size_t done, size_t total) {
  const int width = 40;
  const int filled = static_cast<int>(width * done / std::max<size_t>(total, 1));
  std::fprintf(stderr, "\r[%s%s] %zu/%zu", std::string(static_cast<size_t>(filled), '#').c_str(),
               std::string(static_cast<size_t>(width - filled), ' ').c_str(), done, total);
  if (done == total) std::fprintf(stderr, "\n");
}

void print_summary(const char* name, const ModeSummary& s) {
  fmt::print(
      "{:<8} published {:>5}/{:<5} wrong {:>3}  mean max err x {:6.2f} mm  y {:6.2f} mm  RMSE {:6.2f} mm  "
      "CRLB {:6.2f} mm  RMSE/CRLB {:5.2f} (point beams {:5.2f} mm, {:5.2f})  heading RMSE {:.3f} deg  "
      "recall {:.4f}  false det. {:.4f}\n",
      name, s.published_ok, s.measurements, s.wrong_matches, s.mean_max_err_x_mm, s.mean_max_err_y_mm,
      s.rmse_mm, s.crlb_rmse_mm, s.crlb_ratio, s.point_beam_crlb_rmse_mm, s.point_beam_crlb_ratio,
      s.heading_rmse_deg, s.recall, s.false_detection_rate);
}

void print_paper_table(const StudyResult& r, const std::vector<Pose2>& poses, int repeats) {
  fmt::print("Table 1 protocol: robot static at 10 positions, {} measurements each (mm)\n", repeats);
  for (PipelineMode mode : {PipelineMode::kPaper, PipelineMode::kDefault}) {
    fmt::print("\nmode {}\n{:>3}  {:<48} {:<14} {:<18} {:>6} {:>6}\n", to_string(mode), "No", "measured",
               "actual", "(dx_max, dy_max)", "RMSE", "CRLB");
    for (size_t p = 0; p < poses.size(); ++p) {
      std::string measured;
      double dx = 0.0, dy = 0.0, sum_e2 = 0.0, sum_crlb = 0.0;
      int n_e = 0, n_crlb = 0;
      for (const auto& m : r.measurements) {
        if (m.mode != mode || m.pose_index != static_cast<int>(p)) continue;
        if (m.has_crlb) {
          sum_crlb += m.crlb_var_xy;
          ++n_crlb;
        }
        if (!m.published_ok) {
          measured += "(  no pose  ) ";
          continue;
        }
        measured += fmt::format("({:.1f}, {:.1f}) ", 1000 * m.estimate.x, 1000 * m.estimate.y);
        dx = std::max(dx, std::abs(m.estimate.x - m.truth.x));
        dy = std::max(dy, std::abs(m.estimate.y - m.truth.y));
        sum_e2 += (m.estimate.translation() - m.truth.translation()).squaredNorm();
        ++n_e;
      }
      const std::string rmse = n_e > 0 ? fmt::format("{:.2f}", 1000 * std::sqrt(sum_e2 / n_e)) : "-";
      const std::string crlb = n_crlb > 0 ? fmt::format("{:.2f}", 1000 * std::sqrt(sum_crlb / n_crlb)) : "-";
      fmt::print("{:>3}  {:<48} {:<14} {:<18} {:>6} {:>6}\n", p + 1, measured,
                 fmt::format("({:.0f}, {:.0f})", 1000 * poses[p].x, 1000 * poses[p].y),
                 fmt::format("({:.1f}, {:.1f})", 1000 * dx, 1000 * dy), rmse, crlb);
    }
    fmt::print("RMSE and CRLB: position error over the measurements (mm); CRLB of the LMS100 beam spot\n");
  }
  fmt::print("\npaper (LabVIEW, real LMS100): mean max err x 14.30 mm  y 14.70 mm\n");
}

std::vector<Eigen::Vector2d> errors_mm(const StudyResult& r, PipelineMode mode) {
  std::vector<Eigen::Vector2d> e;
  for (const auto& m : r.measurements) {
    if (m.mode == mode && m.published_ok && !m.wrong) {
      e.push_back(1000.0 * Eigen::Vector2d(m.estimate.x - m.truth.x, m.estimate.y - m.truth.y));
    }
  }
  return e;
}

/// The paper's own Table 1 errors (measured minus actual), for the plot.
std::vector<Eigen::Vector2d> paper_reported_errors_mm() {
  const double d[30][2] = {
      {5, 10},   {-12, 9},  {12, 13}, {8, 11}, {-9, 12}, {17, -14}, {10, -11}, {6, 9},   {-11, 15}, {7, 11},
      {10, 9},   {-12, 15}, {20, 9},  {-9, 7}, {6, 10},  {-6, 7},   {6, 11},   {8, 10},  {60, 15},  {7, 8},
      {-10, 13}, {14, 17},  {23, 8},  {9, 4},  {15, 1},  {-10, 18}, {12, 11},  {16, 19}, {11, 13},  {12, 15}};
  std::vector<Eigen::Vector2d> e;
  for (const auto& p : d) e.emplace_back(p[0], p[1]);
  return e;
}

int run(const std::string& command, Options o) {
  const bool paper_table = command == "paper-table";
  if (o.world_file.empty())
    o.world_file = paper_table ? "deploy/config/paper_cell.json" : "deploy/config/world_demo.json";
  if (o.out_prefix.empty()) {
    o.out_prefix = !o.json_file.empty() && o.json_file.size() > 5 &&
                           o.json_file.compare(o.json_file.size() - 5, 5, ".json") == 0
                       ? o.json_file.substr(0, o.json_file.size() - 5)
                       : "logs/refloc-eval-" + command;
  }
  const sim::World world = sim::load_world(o.world_file);
  const ReflectorMap map = load_reflector_map(world.map_file);
  const RobotConfig robot = load_robot_config(o.robot_file);
  StudyConfig config;
  config.range_sigma = o.sigma_mm / 1000.0;
  config.range_offset = o.offset_mm / 1000.0;
  config.seed = o.seed;
  config.repeats = paper_table ? o.repeats : 1;
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
  paper_configs.extractor.extractor.clustering.range_sigma = config.range_sigma;
  default_configs.extractor.extractor.clustering.range_sigma = config.range_sigma;
  const StudyResult r = run_study(world, map, robot.robot_T_laser, paper_configs, default_configs, poses,
                                  config, o.progress ? ProgressCallback(print_progress) : ProgressCallback());
  if (paper_table) print_paper_table(r, poses, config.repeats);
  fmt::print("\n{} over {} poses x {} scans, sigma {:.1f} mm, offset {:.1f} mm, world {}\n", command,
             poses.size(), config.repeats, o.sigma_mm, o.offset_mm, o.world_file);
  print_summary("paper", r.paper);
  print_summary("default", r.default_mode);

  nlohmann::json j;
  j["command"] = command;
  j["world"] = o.world_file;
  j["sigma_mm"] = o.sigma_mm;
  j["offset_mm"] = o.offset_mm;
  j["seed"] = o.seed;
  j["scans_per_pose"] = config.repeats;
  j["modes"]["paper"] = to_json(r.paper);
  j["modes"]["default"] = to_json(r.default_mode);
  if (paper_table) j["paper_reported"] = {{"mean_max_err_x_mm", 14.3}, {"mean_max_err_y_mm", 14.7}};
  if (!o.json_file.empty()) std::ofstream(o.json_file) << j.dump(2) << "\n";
  std::ofstream(o.out_prefix + ".csv") << measurements_csv(r.measurements);
  std::vector<PlotSeries> series = {
      {"paper mode error [mm]", "#ff7f0e", errors_mm(r, PipelineMode::kPaper), true},
      {"default mode error [mm]", "#1f77b4", errors_mm(r, PipelineMode::kDefault), true}};
  if (paper_table)
    series.insert(series.begin(),
                  {"paper's Table 1 (real) [mm]", "#999999", paper_reported_errors_mm(), true});
  write_path_plot_svg(o.out_prefix + ".svg",
                      fmt::format("refloc-eval {}: position error (x, y) per scan [mm]", command), series);
  fmt::print("wrote {}.csv and {}.svg{}\n", o.out_prefix, o.out_prefix,
             o.json_file.empty() ? "" : " and " + o.json_file);
  return 0;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Accuracy studies of refloc's localization in simulation (LMS100 error model)"};
  app.require_subcommand(1);
  refloc::Options o;
  auto add_common = [&o](CLI::App* c) {
    c->add_option("--world", o.world_file, "world file (default: paper_cell.json / world_demo.json)");
    c->add_option("--robot", o.robot_file, "robot config (laser mount)")->capture_default_str();
    c->add_option("--extractor-config", o.extractor_file,
                  "reflector_extractor config ('mode' is set per pipeline)")
        ->capture_default_str();
    c->add_option("--matcher-config", o.matcher_file,
                  "reflector_matcher config (its map_file is not used: the world's map is)")
        ->capture_default_str();
    c->add_option("--solver-config", o.solver_file, "pose_solver config")->capture_default_str();
    c->add_option("--sigma-mm", o.sigma_mm, "LMS100 range noise, 1 sigma [mm]")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 200.0));
    c->add_option("--offset-mm", o.offset_mm, "systematic range offset [mm]")
        ->capture_default_str()
        ->check(CLI::Range(-100.0, 100.0));
    c->add_option("--seed", o.seed, "random seed")->capture_default_str();
    c->add_option("--json", o.json_file, "write the summary as JSON (CSV and SVG go next to it)");
    c->add_option(
        "--out-prefix", o.out_prefix,
        "path prefix of the CSV and SVG (default: next to --json, else logs/refloc-eval-<command>)");
    c->add_flag("--progress,!--no-progress", o.progress, "progress bar on stderr");
  };
  CLI::App* table =
      app.add_subcommand("paper-table", "the paper's Table 1: 10 static positions, 3 scans each");
  add_common(table);
  table->add_option("--repeats", o.repeats, "scans per position")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  CLI::App* random = app.add_subcommand("random", "random poses in a world: accuracy, wrong matches, recall");
  add_common(random);
  random->add_option("--n", o.n, "number of poses")->capture_default_str()->check(CLI::Range(1, 10000000));
  CLI11_PARSE(app, argc, argv);
  const std::string command = table->parsed() ? "paper-table" : "random";
  return refloc::guarded_main("refloc-eval", [&] { return refloc::run(command, o); });
}
