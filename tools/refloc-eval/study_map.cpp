#include "study_map.hpp"

#include "common/json_config.hpp"
#include "world_renderer/world_occluders.hpp"

namespace refloc {

ReflectorMap study_map(const sim::World& world, const std::string& map_file, const std::string& occluders) {
  ReflectorMap map = load_reflector_map(map_file.empty() ? world.map_file : map_file);
  if (occluders == "world") {
    map.occluders = sim::world_occluders(world);
  } else if (occluders == "none") {
    map.occluders.clear();
  } else if (occluders != "map") {
    throw ConfigError("occluders '" + occluders + "': expected map, world or none");
  }
  return map;
}

size_t occluder_segment_count(const std::vector<MapOccluder>& occluders) {
  size_t n = 0;
  for (const MapOccluder& o : occluders) {
    if (o.map_points.size() >= 2)
      n += o.map_points.size() - 1 + (o.closed && o.map_points.size() > 2 ? 1 : 0);
  }
  return n;
}

}  // namespace refloc
