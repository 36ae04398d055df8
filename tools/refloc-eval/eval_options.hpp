#pragma once
// The command line of refloc-eval paper-table and random (header only: main.cpp's part).

#include "eval_command.hpp"

#include <CLI/CLI.hpp>

namespace refloc {

inline void add_eval_options(CLI::App* c, EvalOptions& o) {
  c->add_option("--world", o.world_file, "world file (default: paper_cell.json / world_demo.json)");
  c->add_option("--map", o.map_file, "map the localization loads (default: the world's map_file)");
  c->add_option("--occluders", o.occluders,
                "the matcher's walls: map (the map file's), world (the world's walls and obstacles), none")
      ->capture_default_str()
      ->check(CLI::IsMember({"map", "world", "none"}));
  c->add_option("--robot", o.robot_file, "robot config (laser mount)")->capture_default_str();
  c->add_option("--extractor-config", o.extractor_file,
                "reflector_extractor config ('mode' is set per pipeline)")
      ->capture_default_str();
  c->add_option("--matcher-config", o.matcher_file,
                "reflector_matcher config (its map_file is not used: --map or the world's map is)")
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

}  // namespace refloc
