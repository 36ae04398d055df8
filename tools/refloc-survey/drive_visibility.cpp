#include "drive_visibility.hpp"

#include "common/plane_geometry.hpp"

#include <cmath>

namespace refloc {
namespace {

/// Proper intersection of segments p-p2 and q-q2 (touching counts).
bool segments_cross(const Eigen::Vector2d& p, const Eigen::Vector2d& p2, const Eigen::Vector2d& q,
                    const Eigen::Vector2d& q2) {
  const Eigen::Vector2d r = p2 - p, s = q2 - q;
  const double denominator = cross2(r, s);
  if (std::abs(denominator) < 1e-12) return false;  // parallel: a wall along the line of sight hides nothing
  const double t = cross2(q - p, s) / denominator;
  const double u = cross2(q - p, r) / denominator;
  return t >= 0.0 && t <= 1.0 && u >= 0.0 && u <= 1.0;
}

}  // namespace

bool line_of_sight_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const std::vector<MapOccluder>& occluders) {
  for (const MapOccluder& o : occluders) {
    const size_t n = o.map_points.size();
    for (size_t i = 0; i + 1 < n + (o.closed ? 1 : 0); ++i)
      if (segments_cross(a, b, o.map_points[i], o.map_points[(i + 1) % n])) return true;
  }
  return false;
}

std::vector<VisibilityCount> count_visibility(const std::vector<Pose2>& map_T_robot,
                                              const Pose2& robot_T_laser,
                                              const std::vector<Eigen::Vector2d>& map_p_landmark,
                                              const std::vector<std::vector<char>>& seen_in_scan,
                                              const std::vector<MapOccluder>& occluders,
                                              const VisibilityConfig& config) {
  std::vector<VisibilityCount> out(map_p_landmark.size());
  for (size_t k = 0; k < map_T_robot.size(); ++k) {
    const Pose2 map_T_laser = map_T_robot[k] * robot_T_laser;
    const Pose2 laser_T_map = map_T_laser.inverse();
    for (size_t j = 0; j < map_p_landmark.size(); ++j) {
      const Eigen::Vector2d laser_p = laser_T_map * map_p_landmark[j];
      const double range = laser_p.norm();
      if (range > config.max_range || range <= config.near_end_margin) continue;
      if (std::abs(std::atan2(laser_p.y(), laser_p.x())) > 0.5 * config.field_of_view) continue;
      const Eigen::Vector2d from = map_T_laser.translation();
      const Eigen::Vector2d to = from + (map_p_landmark[j] - from) * (1.0 - config.near_end_margin / range);
      if (line_of_sight_blocked(from, to, occluders)) continue;
      ++out[j].expected;
      if (seen_in_scan[j][k]) ++out[j].seen;
    }
  }
  return out;
}

}  // namespace refloc
