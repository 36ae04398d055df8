#pragma once
// refloc-survey drive and refloc-survey compare: their options and what they run (main.cpp
// only dispatches).

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace refloc {

struct DriveCommandOptions {
  std::string log_path;
  bool live = false;        ///< record the drive from the bus first (drive_live.hpp)
  std::string record_path;  ///< live: the log written; empty: --out with the extension .lcmlog
  std::string lcm_url;      ///< live
  double duration_s = 0.0;  ///< live: 0 = until Ctrl-C
  double timeout_s = 10.0;  ///< live: stop after this long without a scan
  std::string robot_path = "deploy/config/robot.json";
  std::string extractor_path = "deploy/config/reflector_extractor.json";
  std::string out_path;
  std::string anchors_path;
  std::string report_dir;
  std::string truth_path;     ///< simulation: drawn in the picture and compared (refloc-survey compare)
  std::string truth_channel;  ///< simulation: the true poses, to judge the detections themselves
  std::string map_id = "surveyed";
  std::vector<double> start_pose = {0.0, 0.0, 0.0};  ///< x_m, y_m, theta_rad
  bool estimate_range_bias = true;
  /// Extract with mapping_corrections() (the wall behind, the fit's second-order bias).
  bool mapping_corrections = true;
  /// BundleOptions::same_view_beam_steps (0: every detection independent) [beam steps].
  double same_view_beam_steps = 0.5;
  double same_view_range_m = 0.05;  ///< BundleOptions::same_view_range_m [m]
  double scale_sigma_ppm = 200.0;   ///< DriveSurveyConfig::scale_sigma_ppm [1e-6]
  bool force = false;               ///< replace an existing out_path
};

struct CompareCommandOptions {
  std::string map_path;
  std::string truth_path;
  bool align = true;
  double match_gate_m = 0.1;
};

/// Adds the subcommand "drive" filling o; shipped default paths resolved.
CLI::App* add_drive_command(CLI::App& app, DriveCommandOptions& o);
int run_drive_command(const DriveCommandOptions& o);

CLI::App* add_compare_command(CLI::App& app, CompareCommandOptions& o);
int run_compare_command(const CompareCommandOptions& o);

}  // namespace refloc
