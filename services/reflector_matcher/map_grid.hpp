#pragma once
// A uniform grid over the map's reflectors so "reflectors within r of a point"
// costs a few cells instead of the whole map (1000-reflector maps).

#include "common/reflector_map.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

class MapGrid {
 public:
  /// cell_size [m], typically about half the query radius.
  MapGrid(const ReflectorMap& map, double cell_size);

  /// Appends to out the indices of reflectors within radius [m] of centre (out is not cleared).
  void query(const Eigen::Vector2d& centre, double radius, std::vector<int>& out) const;

 private:
  const ReflectorMap* map_;
  double cell_size_;
  Eigen::Vector2d origin_;
  int nx_ = 1, ny_ = 1;
  std::vector<uint32_t>
      cell_begin_;  ///< CSR: reflectors of cell c are items_[cell_begin_[c] .. cell_begin_[c+1])
  std::vector<int> items_;
};

}  // namespace refloc
