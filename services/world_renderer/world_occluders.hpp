#pragma once
// A world's walls and obstacles as map occluders, so studies can give the matcher
// the world's walls before a map file carries them (format v2).

#include "common/reflector_map.hpp"
#include "world_renderer/world.hpp"

#include <vector>

namespace refloc::sim {

/// The world's diffuse segments (walls and obstacles: racks, pillars) as occluder polylines,
/// consecutive segments joined as the world file listed them (closed when the chain returns to
/// its start). Distractors are left out: tape and metal sheets lie flat on a wall and hide
/// nothing the wall does not.
std::vector<MapOccluder> world_occluders(const World& world);

}  // namespace refloc::sim
