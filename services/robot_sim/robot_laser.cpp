#include "robot_sim/robot_laser.hpp"

#include "lms100_emulator/scan_render_source.hpp"
#include "world_renderer/world_loader.hpp"

#include <utility>

namespace refloc {

std::unique_ptr<Lms100Emulator> make_robot_laser(const SimSetup& setup, sim::PoseAtTime map_T_laser_at) {
  if (setup.world_path.empty()) return nullptr;
  auto world = std::make_shared<const sim::World>(sim::load_world(setup.world_path));
  ScanSource source = sim::make_rendered_scan_source(world, std::move(map_T_laser_at), setup.render,
                                                     setup.emulator.random_seed);
  return std::make_unique<Lms100Emulator>(setup.emulator, std::move(source));
}

}  // namespace refloc
