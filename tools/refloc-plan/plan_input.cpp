#include "plan_input.hpp"

#include "common/json_config.hpp"
#include "world_renderer/world_loader.hpp"
#include "world_renderer/world_occluders.hpp"

namespace refloc {

PlanInput load_plan_input(const std::string& map_file, const std::string& world_file,
                          const std::string& occluders) {
  if (map_file.empty() && world_file.empty()) throw ConfigError("give --map, --world or both");
  if (occluders != "auto" && occluders != "map" && occluders != "world" && occluders != "none") {
    throw ConfigError("--occluders '" + occluders + "': expected auto, map, world or none");
  }
  if (occluders == "world" && world_file.empty()) throw ConfigError("--occluders world needs --world");
  PlanInput input;
  sim::World world;
  if (!world_file.empty()) {
    world = sim::load_world(world_file);
    input.has_world = true;
    input.drivable = world.drivable_areas;
  }
  input.map_name = map_file.empty() ? world.map_file : map_file;
  // The map as the matcher loads it (not the world's reflectors with its simulated map errors).
  input.map = load_reflector_map(input.map_name);
  const bool use_world = occluders == "world" || (occluders == "auto" && input.map.occluders.empty());
  if (occluders == "none") input.map.occluders.clear();
  if (use_world && !world_file.empty()) input.map.occluders = sim::world_occluders(world);
  input.world = std::move(world);
  return input;
}

}  // namespace refloc
