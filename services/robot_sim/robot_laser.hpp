#pragma once
// robot_sim's laser: the emulated LMS100 (services/lms100_emulator) whose scans the world
// renderer draws beam by beam from the laser's true pose at each beam's time.

#include "lms100_emulator/lms100_emulator.hpp"
#include "robot_sim/sim_setup.hpp"
#include "world_renderer/scan_renderer.hpp"

#include <memory>

namespace refloc {

/// The emulated LMS100 for setup.world_path (not started), or null when there is no world;
/// map_T_laser_at gives the laser's true pose at a beam's time and is called from the
/// emulator's thread. Throws ConfigError when the world file is bad.
std::unique_ptr<Lms100Emulator> make_robot_laser(const SimSetup& setup, sim::PoseAtTime map_T_laser_at);

}  // namespace refloc
