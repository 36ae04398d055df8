#include "robot_sim/plant_config_file.hpp"

#include "common/json_config.hpp"

#include <cmath>
#include <limits>

namespace refloc {
namespace {

// Read even when absent (then every wheel keeps 0), so --print-config and the parameter
// reference list the key.
WheelArray read_wheel_array(const JsonConfig& config, const ConfigKey& key, double min, double max) {
  WheelArray values{};
  const std::string& pointer = key.pointer;
  const bool present = config.has(pointer);
  const size_t n = config.array_size(key, false);
  if (!present) return values;
  if (n != 4) config.fail(pointer, "expected 4 values (front-left, front-right, rear-right, rear-left)");
  for (size_t i = 0; i < 4; ++i) {
    values[i] = config.required_number({pointer + "/" + std::to_string(i), key.unit,
                                        "one wheel's value (front-left, front-right, rear-right, rear-left)"},
                                       min, max);
  }
  return values;
}

}  // namespace

PlantSetup parse_plant_setup(const JsonConfig& config) {
  PlantSetup s;
  s.initial_map_T_robot.x = config.number(
      {"/initial_pose/x_m", "m", "true start position x in the map frame; put it inside the world's walls"},
      0.0, -1e4, 1e4);
  s.initial_map_T_robot.y =
      config.number({"/initial_pose/y_m", "m", "true start position y in the map frame"}, 0.0, -1e4, 1e4);
  s.initial_map_T_robot.theta = config.number(
      {"/initial_pose/theta_rad", "rad", "true start heading (robot +x against map +x, counter-clockwise)"},
      0.0, -M_PI, M_PI);
  s.plant.step = config.number(
      {"/step_s", "s",
       "internal integration step of the true motion; smaller is more exact and costs more CPU"},
      s.plant.step, 1e-5, 0.01);
  s.plant.command_timeout = config.number(
      {"/command_timeout_s", "s",
       "a CMD_VEL older than this stops the wheels (ramped down like a motor controller's watchdog)"},
      s.plant.command_timeout, 0.01, 10.0);
  s.encoder_start_ticks =
      config.integer({"/encoder_start_ticks", "count",
                      "encoder count of every wheel at start; near 2^31 the counts wrap soon, testing the "
                      "odometry's wrap handling"},
                     0, std::numeric_limits<int32_t>::min(), std::numeric_limits<int32_t>::max());
  SlipConfig& slip = s.plant.slip;
  slip.scale_error = read_wheel_array(
      config,
      {"/slip/scale_error", "",
       "per wheel [FL, FR, RR, RL]: ground speed / wheel speed - 1 (-0.01: moves 1 % less); unseen by the "
       "encoders, so odometry drifts; absent: 0"},
      -0.5, 0.5);
  slip.spin_excess = read_wheel_array(
      config,
      {"/slip/spin_excess", "",
       "per wheel [FL, FR, RR, RL]: extra spin that moves nothing (lost traction); the encoders see it, the "
       "odometry's slip indicator should flag it; absent: 0"},
      -0.5, 5.0);
  slip.lateral_noise_per_speed = config.number(
      {"/slip/lateral_noise_per_speed", "(m/s)/(m/s)",
       "sideways slip: std dev of random body-y velocity per m/s of speed, drawn every step; 0 = none"},
      slip.lateral_noise_per_speed, 0.0, 1.0);
  slip.seed = static_cast<unsigned>(config.integer(
      {"/slip/seed", "",
       "random seed of the lateral slip noise; change it for another, still reproducible, run"},
      slip.seed, 0, 4294967295LL));
  return s;
}

}  // namespace refloc
