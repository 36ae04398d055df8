#pragma once
// The command line of refloc-eval drive (header only: main.cpp's part).

#include "drive_command.hpp"

#include <CLI/CLI.hpp>

namespace refloc {

inline void add_drive_options(CLI::App* c, DriveOptions& o) {
  c->add_option("--world", o.world_file, "world file (the loop is world_demo.json's ring corridor)")
      ->capture_default_str();
  c->add_option("--map", o.map_file, "map the localization loads (default: the world's map_file)");
  c->add_option("--occluders", o.occluders,
                "the matcher's walls: map (the map file's), world (the world's walls and obstacles), none")
      ->capture_default_str()
      ->check(CLI::IsMember({"map", "world", "none"}));
  c->add_option("--robot", o.robot_file, "robot config (laser mount)")->capture_default_str();
  c->add_option("--extractor-config", o.extractor_file, "reflector_extractor config")->capture_default_str();
  c->add_option("--matcher-config", o.matcher_file, "reflector_matcher config")->capture_default_str();
  c->add_option("--solver-config", o.solver_file, "pose_solver config")->capture_default_str();
  c->add_option("--speed-mps", o.speed_mps, "driving speed [m/s]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3.0));
  c->add_option("--duration-s", o.duration_s, "simulated time [s]; 0: one lap")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 36000.0));
  c->add_option("--warmup-s", o.warmup_s, "fixes before this are not scored (matcher cold start) [s]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 3600.0));
  c->add_option("--heading", o.heading, "tangent: face the way driven; fixed: Mecanum crab, heading held")
      ->capture_default_str()
      ->check(CLI::IsMember({"tangent", "fixed"}));
  c->add_option("--sigma-mm", o.sigma_mm, "LMS100 range noise, 1 sigma [mm]")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 200.0));
  c->add_option("--seed", o.seed, "random seed (the same scans for every source)")->capture_default_str();
  c->add_option("--fix-window-s", o.fix_window_s, "override the extractor's fix_velocity/window_s [s]")
      ->check(CLI::Range(0.0, 2.0));
  c->add_flag("--odometry", o.odometry_only, "run with ODOMETRY (and LASER_POSE fed back)");
  c->add_flag("--no-odometry", o.no_odometry_only, "run without ODOMETRY: the fixes' twist");
  c->add_flag("--no-compensation", o.no_compensation_only, "run with motion_compensation false");
  c->add_option("--json", o.json_file, "write the summary as JSON");
}

}  // namespace refloc
