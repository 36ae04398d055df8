// refloc-eval: accuracy studies of the localization pipeline in simulation.
//   refloc-eval paper-table   the paper's Table 1 protocol, both modes side by side
//   refloc-eval random --n N  random poses of a world; also wrong matches, recall, false detections
//   refloc-eval drive         a robot driving a loop: motion compensation by odometry, fixes, none

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "drive_command.hpp"
#include "drive_options.hpp"
#include "eval_command.hpp"

#include <CLI/CLI.hpp>

namespace refloc {
namespace {

void add_common_options(CLI::App* c, EvalOptions& o) {
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
  c->add_option("--range-scale-ppm", o.range_scale_ppm,
                "range-proportional error [1e-6 of the range]; 1500 = +30 mm at 20 m")
      ->capture_default_str()
      ->check(CLI::Range(-20000.0, 20000.0));
  c->add_option("--range-walk-mm", o.range_walk_mm,
                "range walk of bright echoes (RSSI >= --range-walk-rssi-bright: reflectors) [mm]")
      ->capture_default_str()
      ->check(CLI::Range(-100.0, 100.0));
  c->add_option("--range-walk-weak-mm", o.range_walk_weak_mm,
                "range walk of weak echoes (RSSI <= --range-walk-rssi-weak: walls) [mm]; linear between")
      ->capture_default_str()
      ->check(CLI::Range(-100.0, 100.0));
  c->add_option("--range-walk-rssi-weak", o.range_walk_rssi_weak,
                "RSSI of the weak walk level [16-bit units]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 65534.0));
  c->add_option("--range-walk-rssi-bright", o.range_walk_rssi_bright,
                "RSSI of the bright walk level [16-bit units], above the weak one")
      ->capture_default_str()
      ->check(CLI::Range(1.0, 65535.0));
  c->add_option("--retro-range-bias-mm", o.retro_range_bias_mm,
                "extra range of the retro-reflective part of a spot [mm]")
      ->capture_default_str()
      ->check(CLI::Range(-100.0, 100.0));
  c->add_option("--rssi-scale", o.rssi_scale,
                "what the 16-bit RSSI channel carries: 16bit, or 8bit_in_16bit (values 0..255)")
      ->capture_default_str()
      ->check(CLI::IsMember({"16bit", "8bit_in_16bit"}));
  c->add_option("--seed", o.seed, "random seed")->capture_default_str();
  c->add_option(
       "--scan-spacing-s", o.scan_spacing_s,
       "time between scans; above the matcher's prior_max_age_s (0.5) every scan starts without a prior")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 3600.0));
  c->add_option("--json", o.json_file, "write the summary as JSON (CSV and SVG go next to it)");
  c->add_option("--out-prefix", o.out_prefix,
                "path prefix of the CSV and SVG (default: next to --json, else logs/refloc-eval-<command>)");
  c->add_flag("--progress,!--no-progress", o.progress, "progress bar on stderr");
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Accuracy studies of refloc's localization in simulation (LMS100 error model)"};
  refloc::add_version_flag(app, "refloc-eval");
  app.require_subcommand(1);
  refloc::EvalOptions o;
  // Shipped files from the refloc root, so refloc-eval runs from any working directory.
  for (std::string* file : {&o.robot_file, &o.extractor_file, &o.matcher_file, &o.solver_file})
    *file = refloc::shipped_path(*file);
  CLI::App* table =
      app.add_subcommand("paper-table", "the paper's Table 1: 10 static positions, 3 scans each");
  refloc::add_common_options(table, o);
  table->add_option("--repeats", o.repeats, "scans per position")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  CLI::App* random = app.add_subcommand("random", "random poses in a world: accuracy, wrong matches, recall");
  refloc::add_common_options(random, o);
  random->add_option("--n", o.n, "number of poses")->capture_default_str()->check(CLI::Range(1, 10000000));
  refloc::DriveOptions d;
  for (std::string* file : {&d.world_file, &d.robot_file, &d.extractor_file, &d.matcher_file, &d.solver_file})
    *file = refloc::shipped_path(*file);
  CLI::App* drive = app.add_subcommand(
      "drive", "a moving robot's consecutive scans: motion compensation with odometry, from fixes, none");
  refloc::add_drive_options(drive, d);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  if (drive->parsed())
    return refloc::guarded_main("refloc-eval", [&] { return refloc::run_drive_command(d); });
  const std::string command = table->parsed() ? "paper-table" : "random";
  return refloc::guarded_main("refloc-eval", [&] { return refloc::run_eval(command, o); });
}
