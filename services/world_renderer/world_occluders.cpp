#include "world_renderer/world_occluders.hpp"

#include <string>

namespace refloc::sim {

std::vector<MapOccluder> world_occluders(const World& world) {
  std::vector<MapOccluder> occluders;
  bool chain_open = false;  // the last occluder can still grow by the next segment
  for (const WorldSegment& s : world.segments) {
    if (s.surface != SurfaceKind::kDiffuse) {
      chain_open = false;
      continue;
    }
    // add_polyline appends a polyline's segments in order, each starting where the last ended.
    if (chain_open && occluders.back().map_points.back() == s.map_p_a) {
      MapOccluder& o = occluders.back();
      if (s.map_p_b == o.map_points.front()) {
        o.closed = true;
        chain_open = false;
      } else {
        o.map_points.push_back(s.map_p_b);
      }
      continue;
    }
    MapOccluder o;
    o.name = "world segment chain " + std::to_string(occluders.size() + 1);
    o.map_points = {s.map_p_a, s.map_p_b};
    occluders.push_back(std::move(o));
    chain_open = true;
  }
  return occluders;
}

}  // namespace refloc::sim
