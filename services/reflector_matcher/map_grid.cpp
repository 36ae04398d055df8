#include "reflector_matcher/map_grid.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

MapGrid::MapGrid(const ReflectorMap& map, double cell_size) : map_(&map), cell_size_(cell_size) {
  Eigen::Vector2d lo(0, 0), hi(0, 0);
  if (!map.reflectors.empty()) {
    lo = hi = map.reflectors.front().map_p_center;
    for (const auto& r : map.reflectors) {
      lo = lo.cwiseMin(r.map_p_center);
      hi = hi.cwiseMax(r.map_p_center);
    }
  }
  // Keep the grid bounded for sparse, very large maps.
  constexpr double kMaxCells = 4e6;
  const Eigen::Vector2d extent = hi - lo;
  while ((extent.x() / cell_size_ + 1) * (extent.y() / cell_size_ + 1) > kMaxCells) cell_size_ *= 2.0;
  origin_ = lo;
  nx_ = static_cast<int>(extent.x() / cell_size_) + 1;
  ny_ = static_cast<int>(extent.y() / cell_size_) + 1;

  const auto cell_of = [&](const Eigen::Vector2d& p) {
    const int cx = std::clamp(static_cast<int>((p.x() - origin_.x()) / cell_size_), 0, nx_ - 1);
    const int cy = std::clamp(static_cast<int>((p.y() - origin_.y()) / cell_size_), 0, ny_ - 1);
    return static_cast<size_t>(cy) * static_cast<size_t>(nx_) + static_cast<size_t>(cx);
  };
  const size_t ncells = static_cast<size_t>(nx_) * static_cast<size_t>(ny_);
  cell_begin_.assign(ncells + 1, 0);
  for (const auto& r : map.reflectors) ++cell_begin_[cell_of(r.map_p_center) + 1];
  for (size_t c = 0; c < ncells; ++c) cell_begin_[c + 1] += cell_begin_[c];
  items_.resize(map.reflectors.size());
  std::vector<uint32_t> fill(cell_begin_.begin(), cell_begin_.end() - 1);
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    items_[fill[cell_of(map.reflectors[i].map_p_center)]++] = static_cast<int>(i);
  }
}

void MapGrid::query(const Eigen::Vector2d& centre, double radius, std::vector<int>& out) const {
  const double r2 = radius * radius;
  // Clamp in floating point first: a far-away centre must not overflow the int cast.
  const auto cell = [&](double v, double o, int n) {
    return static_cast<int>(std::clamp(std::floor((v - o) / cell_size_), -1.0, static_cast<double>(n)));
  };
  const int x0 = std::max(0, cell(centre.x() - radius, origin_.x(), nx_));
  const int y0 = std::max(0, cell(centre.y() - radius, origin_.y(), ny_));
  const int x1 = std::min(nx_ - 1, cell(centre.x() + radius, origin_.x(), nx_));
  const int y1 = std::min(ny_ - 1, cell(centre.y() + radius, origin_.y(), ny_));
  for (int cy = y0; cy <= y1; ++cy) {
    for (int cx = x0; cx <= x1; ++cx) {
      const size_t c = static_cast<size_t>(cy) * static_cast<size_t>(nx_) + static_cast<size_t>(cx);
      for (uint32_t k = cell_begin_[c]; k < cell_begin_[c + 1]; ++k) {
        const int i = items_[k];
        if ((map_->reflectors[static_cast<size_t>(i)].map_p_center - centre).squaredNorm() <= r2)
          out.push_back(i);
      }
    }
  }
}

}  // namespace refloc
