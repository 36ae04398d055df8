#pragma once
// refloc-plan's run: read the inputs, plan the grid, suggest, write the report and draw it.

#include <algorithm>
#include <cstdint>
#include <string>
#include <thread>

namespace refloc {

/// Every option of refloc-plan with its default; units in the names.
struct PlanOptions {
  std::string map_file;    ///< "" = the world's map
  std::string world_file;  ///< "" = none (no drivable area)
  std::string occluders = "auto";
  std::string robot_file = "deploy/config/robot.json";
  std::string matcher_file = "deploy/config/reflector_matcher.json";
  std::string extractor_file = "deploy/config/reflector_extractor.json";
  std::string solver_file = "deploy/config/pose_solver.json";
  double resolution_m = 0.25;
  int headings = 8;
  double crlb_limit_mm = 10.0;
  double range_sigma_mm = 12.0;
  int spot_samples = 201;
  bool ambiguity = true;
  int suggest = 0;
  double suggest_spacing_m = 1.0;
  double suggest_resolution_m = 0.5;
  int suggest_headings = 8;
  int suggest_swap_rounds = 2;
  int measure_cells = 0;
  int measure_scans = 5;
  /// Threads predicting the grid's cells (the plan, the suggestions' trial plans) [-].
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  uint64_t seed = 1;
  std::string out_dir = "logs/refloc-plan";
  bool plot = true;
  bool progress = true;
};

/// 0 on success; throws ConfigError for bad input files (guarded_main turns it into exit 2).
int run_plan(const PlanOptions& options);

}  // namespace refloc
