#pragma once
// refloc-eval's two commands: load the world, the robot and the services' configs, run the
// study in both modes, print and write the results.

#include <unistd.h>

#include <cstdint>
#include <string>

namespace refloc {

/// The command line of refloc-eval.
struct EvalOptions {
  std::string world_file;
  /// The map the localization loads; empty: the world's own map file.
  std::string map_file;
  /// The matcher's occluders: "map" (the map file's, none in a v1 file), "world" (the world's
  /// walls and obstacles, sim::world_occluders), "none".
  std::string occluders = "map";
  std::string robot_file = "deploy/config/robot.json";
  std::string extractor_file = "deploy/config/reflector_extractor.json";
  std::string matcher_file = "deploy/config/reflector_matcher.json";
  std::string solver_file = "deploy/config/pose_solver.json";
  double sigma_mm = 12.0;
  double offset_mm = 0.0;
  double range_scale_ppm = 0.0;           ///< Lms100ErrorModel::range_scale_ppm
  double range_walk_mm = 0.0;             ///< walk of bright echoes (range_walk_bright) [mm]
  double range_walk_weak_mm = 0.0;        ///< walk of weak echoes (range_walk_weak) [mm]
  double range_walk_rssi_weak = 30000;    ///< [16-bit units]
  double range_walk_rssi_bright = 60000;  ///< [16-bit units]
  double retro_range_bias_mm = 0.0;       ///< Lms100ErrorModel::retro_range_bias [mm]
  std::string rssi_scale = "16bit";       ///< "16bit" or "8bit_in_16bit"
  uint64_t seed = 1;
  int repeats = 3;
  int n = 1000;
  double scan_spacing_s = 1.0;  ///< StudyConfig::scan_spacing [s]
  std::string json_file;
  std::string out_prefix;
  bool progress = isatty(2) != 0;
};

/// command: "paper-table" or "random". Returns the exit code.
int run_eval(const std::string& command, EvalOptions o);

}  // namespace refloc
