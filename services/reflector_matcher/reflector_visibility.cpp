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

bool sight_beam_blocked(const OccluderGrid& occluders, const Eigen::Vector2d& map_p_laser,
                        const MapReflector& reflector, int b) {
  const Eigen::Vector2d to_center = reflector.map_p_center - map_p_laser;
  const double range = to_center.norm();
  if (range <= reflector.radius) return false;  // inside it: min_range rules it out anyway
  const Eigen::Vector2d along = to_center / range;
  const Eigen::Vector2d across(-along.y(), along.x());
  // Where a beam parallel to the line of sight, side metres off it, meets the cylinder.
  const double side = (b == 0 ? 0.0 : (b == 1 ? -kSightEdgeFraction : kSightEdgeFraction)) * reflector.radius;
  const Eigen::Vector2d map_p_hit = reflector.map_p_center + side * across -
                                    std::sqrt(reflector.radius * reflector.radius - side * side) * along;
  return occluders.blocks(map_p_laser, map_p_hit);
}

LineOfSight line_of_sight(const OccluderGrid& occluders, const Eigen::Vector2d& map_p_laser,
                          const MapReflector& reflector) {
  int blocked = 0;
  for (int b = 0; b < 3; ++b) blocked += sight_beam_blocked(occluders, map_p_laser, reflector, b);
  return blocked == 0 ? LineOfSight::kClear : (blocked == 3 ? LineOfSight::kBlocked : LineOfSight::kPartial);
}

void SightCache::reset(const OccluderGrid* occluders, const Eigen::Vector2d& map_p_laser,
                       size_t predicted_count) {
  occluders_ = occluders != nullptr && !occluders->empty() ? occluders : nullptr;
  map_p_laser_ = map_p_laser;
  if (occluders_ != nullptr) state_.assign(predicted_count, 0);
}

bool SightCache::beam_blocked(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted,
                              size_t k, int b) {
  const auto tested = static_cast<unsigned char>(1u << b), blocked = static_cast<unsigned char>(8u << b);
  if (!(state_[k] & tested)) {
    const MapReflector& r = map.reflectors[static_cast<size_t>(predicted[k].map_index)];
    state_[k] |= tested;
    if (sight_beam_blocked(*occluders_, map_p_laser_, r, b)) state_[k] |= blocked;
  }
  return (state_[k] & blocked) != 0;
}

bool SightCache::hidden(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k) {
  return occluders_ != nullptr && beam_blocked(map, predicted, k, 0) && beam_blocked(map, predicted, k, 1) &&
         beam_blocked(map, predicted, k, 2);
}

bool SightCache::clear(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k) {
  return occluders_ == nullptr ||
         (!beam_blocked(map, predicted, k, 0) && !beam_blocked(map, predicted, k, 1) &&
          !beam_blocked(map, predicted, k, 2));
}

}  // namespace refloc
