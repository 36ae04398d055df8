#include "robot_sim/plant_config_file.hpp"

#include "common/json_config.hpp"

#include <cmath>
#include <limits>

namespace refloc {
namespace {

WheelArray read_wheel_array(const JsonConfig& config, const std::string& pointer, double min, double max) {
  WheelArray values{};
  if (!config.has(pointer)) return values;
  if (config.array_size(pointer) != 4)
    config.fail(pointer, "expected 4 values (front-left, front-right, rear-right, rear-left)");
  for (size_t i = 0; i < 4; ++i) {
    values[i] = config.required_number(pointer + "/" + std::to_string(i), min, max);
  }
  return values;
}

}  // namespace

PlantSetup parse_plant_setup(const JsonConfig& config) {
  PlantSetup s;
  s.initial_map_T_robot.x = config.number("/initial_pose/x_m", 0.0, -1e4, 1e4);
  s.initial_map_T_robot.y = config.number("/initial_pose/y_m", 0.0, -1e4, 1e4);
  s.initial_map_T_robot.theta = config.number("/initial_pose/theta_rad", 0.0, -M_PI, M_PI);
  s.plant.step = config.number("/step_s", s.plant.step, 1e-5, 0.01);
  s.plant.command_timeout = config.number("/command_timeout_s", s.plant.command_timeout, 0.01, 10.0);
  s.encoder_start_ticks = config.integer("/encoder_start_ticks", 0, std::numeric_limits<int32_t>::min(),
                                         std::numeric_limits<int32_t>::max());
  SlipConfig& slip = s.plant.slip;
  slip.scale_error = read_wheel_array(config, "/slip/scale_error", -0.5, 0.5);
  slip.spin_excess = read_wheel_array(config, "/slip/spin_excess", -0.5, 5.0);
  slip.lateral_noise_per_speed =
      config.number("/slip/lateral_noise_per_speed", slip.lateral_noise_per_speed, 0.0, 1.0);
  slip.seed = static_cast<unsigned>(config.integer("/slip/seed", slip.seed, 0, 4294967295LL));
  return s;
}

}  // namespace refloc
