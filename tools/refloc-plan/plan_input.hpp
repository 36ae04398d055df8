#pragma once
// What refloc-plan plans for: the map (its occluders or the world's walls) and the drivable
// area, read with the services' own loaders.

#include "common/reflector_map.hpp"
#include "world_renderer/world.hpp"

#include <string>
#include <vector>

namespace refloc {

struct PlanInput {
  ReflectorMap map;                         ///< reflectors and the occluders planned with
  std::vector<sim::DrivableArea> drivable;  ///< the world's; empty for a map alone
  std::string map_name;                     ///< the map file as given, for titles
  bool has_world = false;
  sim::World world;  ///< the world file's (for rendered scans), when given
};

/// map_file and/or world_file ("" = none; at least one). The map is map_file, else the world's
/// map_file. occluders: "auto" (the map's own if it has any, else the world's walls and
/// obstacles), "map", "world" (needs a world) or "none". Throws ConfigError naming the file or
/// the choice.
PlanInput load_plan_input(const std::string& map_file, const std::string& world_file,
                          const std::string& occluders);

}  // namespace refloc
