#include "robot_sim/sim_setup.hpp"

#include "common/json_config.hpp"
#include "lms100_emulator/emulator_config_loader.hpp"

#include <filesystem>

namespace refloc {

SimSetup parse_sim_setup(const JsonConfig& file, const std::string& base_dir) {
  SimSetup s;
  s.plant = parse_plant_setup(file);
  s.encoder_rate =
      file.number({"/encoder_rate_hz", "Hz", "WHEEL_ENCODERS publish rate of the simulated motor controller"},
                  s.encoder_rate, 1.0, 1000.0);
  s.ground_truth_rate =
      file.number({"/ground_truth_rate_hz", "Hz", "GROUND_TRUTH publish rate (the simulator's true pose)"},
                  s.ground_truth_rate, 1.0, 1000.0);
  s.command_channel = file.string(
      {"/command_channel", "", "LCM channel of the velocity commands the plant follows"}, s.command_channel);
  const std::string world = file.string(
      {"/world_file", "",
       "world the emulated LMS100 sees (reflectors, walls), relative to this file; \"\": no laser"},
      "");
  if (!world.empty()) s.world_path = (std::filesystem::path(base_dir) / world).string();
  // Read even when absent, so --print-config and docs/parameters.md list every key.
  s.render = sim::parse_scan_render_config(file, "/render");
  s.emulator = parse_emulator_config(file.child("/emulator"));
  return s;
}

SimSetup load_sim_setup(const std::string& config_path, const SimOverrides& o) {
  SimSetup s;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    s = parse_sim_setup(file, std::filesystem::path(config_path).parent_path().string());
    file.reject_unknown_keys();
  }
  if (!o.world_path.empty()) s.world_path = o.world_path;
  if (o.no_laser) s.world_path.clear();
  if (o.port >= 0) s.emulator.port = static_cast<uint16_t>(o.port);
  if (!o.sensor_bind_address.empty()) s.emulator.bind_address = o.sensor_bind_address;
  return s;
}

}  // namespace refloc
