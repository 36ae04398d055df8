#pragma once
// refloc-eval drive: the command line, the runs, the printed table and the JSON.

#include <cstdint>
#include <string>

namespace refloc {

struct DriveOptions {
  std::string world_file = "deploy/config/world_demo.json";
  std::string map_file;           ///< the map localized with; "": the world's
  std::string occluders = "map";  ///< study_map: "map", "world" or "none"
  std::string robot_file = "deploy/config/robot.json";
  std::string extractor_file = "deploy/config/reflector_extractor.json";
  std::string matcher_file = "deploy/config/reflector_matcher.json";
  std::string solver_file = "deploy/config/pose_solver.json";
  double speed_mps = 0.8;
  double duration_s = 0.0;  ///< 0: one lap of the loop
  double warmup_s = 2.0;
  std::string heading = "tangent";  ///< "tangent" or "fixed" (Mecanum crab)
  double sigma_mm = 12.0;
  uint64_t seed = 1;
  double fix_window_s = 0.0;  ///< > 0: override the extractor's fix_velocity/window_s
  bool odometry_only = false;
  bool no_odometry_only = false;
  bool no_compensation_only = false;
  std::string json_file;
};

/// Runs the selected sources (all three when none is selected). Returns the exit code.
int run_drive_command(const DriveOptions& o);

}  // namespace refloc
