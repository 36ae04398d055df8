#include "world_renderer/world_visibility.hpp"

#include "common/plane_geometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc::sim {
namespace {

bool segments_intersect(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
  const Eigen::Vector2d r = q - p;
  const Eigen::Vector2d e = b - a;
  const double denom = cross2(r, e);
  if (std::abs(denom) < 1e-12) return false;  // parallel: a grazing sight line is not blocked
  const Eigen::Vector2d w = a - p;
  const double t = cross2(w, e) / denom;
  const double u = cross2(w, r) / denom;
  return t > 0.0 && t < 1.0 && u >= 0.0 && u <= 1.0;
}

}  // namespace

std::vector<int> visible_reflector_ids(const World& world, const Pose2& map_T_laser, double max_range,
                                       double half_fov) {
  std::vector<int> ids;
  const Eigen::Vector2d origin = map_T_laser.translation();
  for (const MapReflector& r : world.reflectors.reflectors) {
    const Eigen::Vector2d to_center = r.map_p_center - origin;
    const double distance = to_center.norm();
    if (distance > max_range || distance <= r.radius) continue;
    const double bearing = angle_diff(std::atan2(to_center.y(), to_center.x()), map_T_laser.theta);
    if (std::abs(bearing) > half_fov) continue;
    const Eigen::Vector2d near_side = origin + to_center * ((distance - r.radius) / distance);
    bool blocked = false;
    for (const WorldSegment& s : world.segments) {
      if (segments_intersect(origin, near_side, s.map_p_a, s.map_p_b)) {
        blocked = true;
        break;
      }
    }
    for (const MapReflector& other : world.reflectors.reflectors) {
      if (blocked) break;
      if (other.id == r.id) continue;
      blocked = point_segment_distance(other.map_p_center, origin, near_side) < other.radius;
    }
    if (!blocked) ids.push_back(r.id);
  }
  return ids;
}

double clearance(const World& world, const Eigen::Vector2d& map_p) {
  double best = std::numeric_limits<double>::infinity();
  for (const WorldSegment& s : world.segments)
    best = std::min(best, point_segment_distance(map_p, s.map_p_a, s.map_p_b));
  for (const MapReflector& r : world.reflectors.reflectors) {
    best = std::min(best, (r.map_p_center - map_p).norm() - r.radius);
  }
  return best;
}

}  // namespace refloc::sim
