#pragma once
// The map's occluders (walls, racks) as straight segments in a uniform grid, so
// "does anything block the line from the laser to this reflector" walks the few
// cells the line crosses (Amanatides-Woo) instead of testing every segment of a
// big map.

#include "common/reflector_map.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

class OccluderGrid {
 public:
  /// Flattens the polylines (closed ones also last -> first) into segments. cell_size [m]
  /// grows for very large, sparse layouts to bound the cell count; a cell_size larger than
  /// the layout gives one cell, i.e. every segment tested for every line.
  explicit OccluderGrid(const std::vector<MapOccluder>& occluders, double cell_size = kDefaultCellSize);

  /// 2 m: fewest instructions per global relocalization in reflector_matcher_bench's demo hall
  /// (20 segments) and rack maps (200 / 2000 segments) among 0.5, 1, 2 and 4 m (callgrind).
  static constexpr double kDefaultCellSize = 2.0;

  bool empty() const { return segments_.empty(); }
  size_t segment_count() const { return segments_.size(); }

  /// True when a segment separates from and to: they lie strictly on opposite sides of the
  /// segment's line, and the segment meets the line between them (touching counts). A line
  /// ending on a wall is therefore not blocked by it; one through a rack corner is.
  bool blocks(const Eigen::Vector2d& map_p_from, const Eigen::Vector2d& map_p_to) const;

 private:
  struct Segment {
    Eigen::Vector2d a, b;
  };
  /// Counts (fill false) or stores (fill true) the segment in every cell it meets.
  void insert(uint32_t segment, bool fill);

  std::vector<Segment> segments_;
  double cell_size_;
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  int nx_ = 1, ny_ = 1;
  std::vector<uint32_t> cell_begin_;  ///< CSR: segments of cell c are items_[cell_begin_[c] .. [c+1])
  std::vector<uint32_t> items_;
};

}  // namespace refloc
