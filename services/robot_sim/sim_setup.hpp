#pragma once
// robot_sim's whole config file (deploy/config/robot_sim.json): the plant keys of
// plant_config_file.hpp plus
//   {"encoder_rate_hz": 100, "ground_truth_rate_hz": 100, "command_channel": "CMD_VEL",
//    "world_file": "world_demo.json", "render": {...}, "emulator": {...}}
// world_file is relative to the config file; "emulator" holds the keys of
// lms100_emulator/emulator_config_loader.hpp, "render" those of world_renderer/scan_renderer.hpp.

#include "lms100_emulator/lms100_emulator.hpp"
#include "robot_sim/plant_config_file.hpp"
#include "world_renderer/scan_renderer.hpp"

#include <string>

namespace refloc {

struct SimSetup {
  PlantSetup plant;
  double encoder_rate = 100.0;       ///< WHEEL_ENCODERS rate [Hz]
  double ground_truth_rate = 100.0;  ///< GROUND_TRUTH rate [Hz]
  std::string world_path;            ///< empty: no laser
  Lms100EmulatorConfig emulator;
  sim::ScanRenderConfig render;
  std::string command_channel = "CMD_VEL";
};

/// Command-line values; empty / -1 / false keep the file's.
struct SimOverrides {
  std::string world_path;  ///< beats world_file
  bool no_laser = false;   ///< no emulated LMS100 at all
  int port = -1;           ///< LMS100 TCP port
  std::string sensor_bind_address;
};

class JsonConfig;

/// Reads robot_sim's keys from a loaded file; world_file is taken relative to base_dir.
SimSetup parse_sim_setup(const JsonConfig& file, const std::string& base_dir);

/// Reads config_path (the defaults when empty), every key checked and unknown keys refused,
/// then applies the overrides; throws ConfigError naming file and key.
SimSetup load_sim_setup(const std::string& config_path, const SimOverrides& overrides);

}  // namespace refloc
