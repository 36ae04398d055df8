#pragma once
// The map a study localizes with: the world's own map file or another one (a surveyed or a
// format-2 map), with the occluders the study asks for, so the same scans can be localized
// with and without the walls in the map.

#include "common/reflector_map.hpp"
#include "world_renderer/world.hpp"

#include <string>

namespace refloc {

/// map_file: the map to load, "" for the world's. occluders: "map" (the map file's; a format-1
/// file has none), "world" (the world's walls and obstacles, sim::world_occluders), "none".
/// Throws ConfigError for a bad map file or an unknown occluders choice.
ReflectorMap study_map(const sim::World& world, const std::string& map_file, const std::string& occluders);

/// Straight segments of the occluders (a closed polyline of n points has n).
size_t occluder_segment_count(const std::vector<MapOccluder>& occluders);

}  // namespace refloc
