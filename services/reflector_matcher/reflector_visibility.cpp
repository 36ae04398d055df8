#include "reflector_matcher/reflector_visibility.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

void predict_reflectors(const ReflectorMap& map, const MapGrid& grid, const Pose2& map_T_laser,
                        const SensorVisibilityConfig& sensor, double margin, std::vector<int>& scratch,
                        std::vector<PredictedReflector>& out) {
  out.clear();
  scratch.clear();
  grid.query(map_T_laser.translation(), sensor.max_range + margin, scratch);
  const Pose2 laser_T_map = map_T_laser.inverse();
  const double half_fov = 0.5 * sensor.field_of_view;
  for (int i : scratch) {
    PredictedReflector p;
    p.map_index = i;
    p.laser_p = laser_T_map * map.reflectors[static_cast<size_t>(i)].map_p_center;
    p.range = p.laser_p.norm();
    if (p.range < sensor.min_range - margin || p.range > sensor.max_range + margin) continue;
    p.bearing = std::atan2(p.laser_p.y(), p.laser_p.x());
    const double angular_margin = p.range > margin ? std::asin(margin / p.range) : M_PI;
    if (std::abs(p.bearing) > half_fov + angular_margin) continue;
    p.in_view = p.range >= sensor.min_range && p.range <= sensor.max_range && std::abs(p.bearing) <= half_fov;
    out.push_back(p);
  }
}

bool is_shadowed(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k) {
  const PredictedReflector& far = predicted[k];
  const double far_half =
      std::asin(std::min(1.0, map.reflectors[static_cast<size_t>(far.map_index)].radius / far.range));
  for (size_t j = 0; j < predicted.size(); ++j) {
    const PredictedReflector& near = predicted[j];
    if (j == k || near.range >= far.range) continue;
    const double near_half =
        std::asin(std::min(1.0, map.reflectors[static_cast<size_t>(near.map_index)].radius / near.range));
    if (std::abs(angle_diff(near.bearing, far.bearing)) < near_half + far_half) return true;
  }
  return false;
}

}  // namespace refloc
