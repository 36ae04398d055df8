#include "world_renderer/world.hpp"

namespace refloc::sim {

const char* surface_kind_name(SurfaceKind kind) {
  switch (kind) {
    case SurfaceKind::kDiffuse:
      return "diffuse";
    case SurfaceKind::kReflectiveTape:
      return "tape";
    case SurfaceKind::kMetal:
      return "metal";
  }
  return "unknown";
}

bool World::is_drivable(const Eigen::Vector2d& map_p) const {
  for (const DrivableArea& area : drivable_areas) {
    if (area.contains(map_p)) return true;
  }
  return false;
}

void add_polyline(World& world, const std::vector<Eigen::Vector2d>& map_points, bool closed,
                  SurfaceKind surface, double remission) {
  const size_t n = map_points.size();
  if (n < 2) return;
  const size_t count = closed && n > 2 ? n : n - 1;
  for (size_t i = 0; i < count; ++i) {
    WorldSegment s;
    s.map_p_a = map_points[i];
    s.map_p_b = map_points[(i + 1) % n];
    s.surface = surface;
    s.remission = remission;
    world.segments.push_back(s);
  }
}

}  // namespace refloc::sim
