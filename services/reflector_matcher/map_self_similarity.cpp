#include "reflector_matcher/map_self_similarity.hpp"

#include "reflector_matcher/map_triangle_index.hpp"
#include "reflector_matcher/rigid_fit_2d.hpp"

#include <cmath>

namespace refloc {
namespace {

int reflectors_on_others(const ReflectorMap& map, const Pose2& move, double tolerance) {
  int count = 0;
  for (const MapReflector& r : map.reflectors) {
    const Eigen::Vector2d moved = move * r.map_p_center;
    for (const MapReflector& other : map.reflectors) {
      if ((moved - other.map_p_center).norm() <= tolerance) {
        ++count;
        break;
      }
    }
  }
  return count;
}

}  // namespace

MapSelfSimilarity find_map_self_similarity(const ReflectorMap& map, double tolerance, double max_side,
                                           size_t max_triangles) {
  MapSelfSimilarity best;
  const MapTriangleIndex index(map, tolerance, 0.3, max_side, max_triangles);
  for (const IndexedTriangle& t : index.triangles()) {
    const std::array<double, 3> sides{t.side[0], t.side[1], t.side[2]};
    index.for_each_candidate(sides, [&](const IndexedTriangle& other) {
      RigidFit2d fit;
      for (int k = 0; k < 3; ++k) {
        fit.add(map.reflectors[static_cast<size_t>(t.opposite[k])].map_p_center,
                map.reflectors[static_cast<size_t>(other.opposite[k])].map_p_center);
      }
      Pose2 move;
      if (!fit.solve(move)) return;
      if (move.translation().norm() < 0.2 && std::abs(move.theta) < 5.0 * M_PI / 180.0) return;
      for (int k = 0; k < 3; ++k) {  // the triangle itself must land within tolerance
        if ((move * map.reflectors[static_cast<size_t>(t.opposite[k])].map_p_center -
             map.reflectors[static_cast<size_t>(other.opposite[k])].map_p_center)
                .norm() > tolerance)
          return;
      }
      const int count = reflectors_on_others(map, move, tolerance);
      if (count > best.reflectors_matched) best = {count, move};
    });
  }
  return best;
}

}  // namespace refloc
