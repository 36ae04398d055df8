#pragma once
// The plant part of robot_sim's config file (deploy/config/robot_sim.json):
//   {"initial_pose": {"x_m", "y_m", "theta_rad"}, "step_s": 0.001, "command_timeout_s": 0.2,
//    "encoder_start_ticks": 0,
//    "slip": {"scale_error": [4], "spin_excess": [4], "lateral_noise_per_speed": 0, "seed": 1}}
// Every key optional with the defaults of the structs.

#include "common/se2.hpp"
#include "robot_sim/mecanum_plant.hpp"

#include <cstdint>
#include <string>

namespace refloc {

class JsonConfig;

struct PlantSetup {
  PlantConfig plant;
  Pose2 initial_map_T_robot;
  int64_t encoder_start_ticks = 0;  ///< count at start; near +-2^31 exercises the wrap downstream
};

/// Reads the keys above; does not call reject_unknown_keys (the file holds more).
PlantSetup parse_plant_setup(const JsonConfig& config);

}  // namespace refloc
