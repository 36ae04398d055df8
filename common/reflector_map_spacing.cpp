#include "common/reflector_map_spacing.hpp"

#include "common/json_config.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {
namespace {

uint64_t key(int64_t cx, int64_t cy) {
  return (static_cast<uint64_t>(cx) << 32) ^ (static_cast<uint64_t>(cy) & 0xffffffffU);
}

}  // namespace

void SpacingCheck::add(const std::vector<MapReflector>& reflectors) {
  const size_t i = reflectors.size() - 1;
  const MapReflector& a = reflectors[i];
  max_radius_ = std::max(max_radius_, a.radius);
  if (2.0 * max_radius_ + kMinReflectorGap_m > cell_)
    regrid(reflectors, 2.0 * (2.0 * max_radius_ + kMinReflectorGap_m));
  const int64_t cx = cell_of(a.map_p_center.x());
  const int64_t cy = cell_of(a.map_p_center.y());
  for (int64_t dx = -1; dx <= 1; ++dx) {
    for (int64_t dy = -1; dy <= 1; ++dy) {
      const auto found = grid_.find(key(cx + dx, cy + dy));
      if (found == grid_.end()) continue;
      for (const size_t j : found->second) check_pair(reflectors, i, j);
    }
  }
  grid_[key(cx, cy)].push_back(i);
}

int64_t SpacingCheck::cell_of(double v) const { return static_cast<int64_t>(std::floor(v / cell_)); }

void SpacingCheck::regrid(const std::vector<MapReflector>& reflectors, double cell) {
  cell_ = cell;
  grid_.clear();
  for (size_t j = 0; j + 1 < reflectors.size(); ++j) {
    const Eigen::Vector2d& p = reflectors[j].map_p_center;
    grid_[key(cell_of(p.x()), cell_of(p.y()))].push_back(j);
  }
}

void SpacingCheck::check_pair(const std::vector<MapReflector>& reflectors, size_t i, size_t j) const {
  const MapReflector& a = reflectors[i];
  const MapReflector& b = reflectors[j];
  const double distance = (a.map_p_center - b.map_p_center).norm();
  const double needed = a.radius + b.radius + kMinReflectorGap_m;
  if (distance >= needed) return;
  config_.fail(
      fmt::format("{}/{}", list_, i),
      fmt::format("reflector id {} is {:.3f} m from id {} at {}/{}; centres must be at least {:.3f} m "
                  "apart (radii {} + {} m + {} m gap)",
                  a.id, distance, b.id, list_, j, needed, a.radius, b.radius, kMinReflectorGap_m));
}

}  // namespace refloc
