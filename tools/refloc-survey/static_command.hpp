#pragma once
// refloc-survey static: its options and what it runs (main.cpp only dispatches).

#include "static_survey.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace refloc {

struct StaticCommandOptions {
  std::vector<double> pose = {0.0, 0.0, 0.0};  ///< map_T_robot x_m, y_m, theta_rad
  int scans = 100;
  std::string log_path;  ///< empty: live from the bus
  std::string lcm_url;
  std::string channel;  ///< empty: the extractor config's input channel (LMS100_SCAN)
  double timeout_s = 10.0;
  std::string robot_path = "deploy/config/robot.json";
  std::string extractor_path = "deploy/config/reflector_extractor.json";
  std::string out_path;
  std::string map_id = "surveyed";
  double range_bias_mm = 0.0;
  double range_bias_sigma_mm = 30.0;
  bool range_bias_stated = false;  ///< set by run: --range-bias-mm or --range-bias-sigma-mm given
  double min_seen_fraction = 0.8;
  bool force = false;
};

/// Adds the subcommand "static" filling o; shipped default paths resolved.
CLI::App* add_static_command(CLI::App& app, StaticCommandOptions& o);
/// Exit 0 map written, 1 fewer than 3 reflectors kept (nothing written), 2 bad input.
int run_static_command(const StaticCommandOptions& o);

}  // namespace refloc
