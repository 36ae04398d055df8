#pragma once
// refloc-plan's command line (header only: main.cpp's part).

#include "plan_command.hpp"

#include <CLI/CLI.hpp>

namespace refloc {

inline void add_plan_options(CLI::App& c, PlanOptions& o) {
  c.add_option("--map", o.map_file, "reflector map, format 1 or 2 (default: the --world's map_file)")
      ->check(CLI::ExistingFile);
  c.add_option("--world", o.world_file,
               "world file: its drivable_areas are the grid, its walls the occluders of a map without any")
      ->check(CLI::ExistingFile);
  c.add_option("--occluders", o.occluders,
               "what hides reflectors: auto (the map's, else the world's walls), map, world, none")
      ->capture_default_str()
      ->check(CLI::IsMember({"auto", "map", "world", "none"}));
  c.add_option("--robot", o.robot_file, "robot config (laser_mount)")->capture_default_str();
  c.add_option("--matcher-config", o.matcher_file,
               "reflector_matcher config: sensor range and field of view, min_matches, the rival rule")
      ->capture_default_str();
  c.add_option("--resolution-m", o.resolution_m, "grid cell side [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  c.add_option("--headings", o.headings, "robot headings per cell, evenly spaced from 0 deg [-]")
      ->capture_default_str()
      ->check(CLI::Range(1, 360));
  c.add_option("--crlb-limit-mm", o.crlb_limit_mm,
               "a cell whose worst-heading CRLB position sigma is above this is inaccurate [mm]")
      ->capture_default_str()
      ->check(CLI::Range(0.001, 10000.0));
  c.add_option("--range-sigma-mm", o.range_sigma_mm, "LMS100 range noise per beam, 1 sigma [mm]")
      ->capture_default_str()
      ->check(CLI::Range(0.1, 1000.0));
  c.add_option("--spot-samples", o.spot_samples,
               "rays across the beam spot in the CRLB (refloc-eval: 201) [-]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1001));
  c.add_flag(
      "--ambiguity,!--no-ambiguity", o.ambiguity,
      "run the matcher's relocalization on each cell's reflectors (default on; off: counts and CRLB only)");
  c.add_option("--suggest", o.suggest, "K: reflectors to suggest along the occluders, greedily [-]")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  c.add_option("--suggest-spacing-m", o.suggest_spacing_m, "between candidate positions along a wall [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.05, 100.0));
  c.add_option("--suggest-resolution-m", o.suggest_resolution_m, "grid the suggestions are chosen on [m]")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 100.0));
  c.add_option("--suggest-headings", o.suggest_headings, "headings the suggestions are chosen at [-]")
      ->capture_default_str()
      ->check(CLI::Range(1, 360));
  c.add_option(
       "--suggest-swap-rounds", o.suggest_swap_rounds,
       "after the greedy choice, rounds of swapping each suggestion for a better candidate; 0 = greedy "
       "only [-]")
      ->capture_default_str()
      ->check(CLI::Range(0, 100));
  c.add_option("--measure-cells", o.measure_cells,
               "check the prediction: render scans at this many random cells (every heading) through "
               "refloc-eval's pipeline; needs --world; 0 = off [-]")
      ->capture_default_str()
      ->check(CLI::Range(0, 1000000));
  c.add_option("--measure-scans", o.measure_scans, "rendered scans per measured pose [-]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1000));
  c.add_option("--seed", o.seed, "random seed of the measured cells and the sensor noise")
      ->capture_default_str();
  c.add_option("--threads", o.threads,
               "threads predicting the grid's cells, each with its own matcher and beam tracer; the plan "
               "is the same for any number (default: the machine's hardware threads) [-]")
      ->capture_default_str()
      ->check(CLI::Range(1, 1024));
  c.add_option("--extractor-config", o.extractor_file,
               "reflector_extractor config: energy threshold and min_beams (a reflector is seen when that "
               "many beams are bright), and the measurement's")
      ->capture_default_str();
  c.add_option("--solver-config", o.solver_file,
               "pose_solver config: whether the matches make a pose, and the measurement's")
      ->capture_default_str();
  c.add_option("--out-dir", o.out_dir, "folder for grid.json, summary.txt, plan.png, plan.svg")
      ->capture_default_str();
  c.add_flag("--plot,!--no-plot", o.plot,
             "draw plan.png/.svg with tools/refloc-plot/refloc-plot.py plan (default on)");
  c.add_flag("--progress,!--no-progress", o.progress, "progress bar on stderr (default on)");
}

}  // namespace refloc
