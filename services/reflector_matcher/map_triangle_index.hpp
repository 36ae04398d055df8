#pragma once
// Every triangle of map reflectors a scan could see (all sides <= max side),
// keyed by its sorted side lengths in a hash of cubic cells, built once per map.
// A triangle measured in the laser frame finds its map candidates in <= 8 cells.

#include "reflector_matcher/triangle_signature.hpp"

#include "common/reflector_map.hpp"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace refloc {

struct IndexedTriangle {
  std::array<float, 3> side{};        ///< [m], ascending
  std::array<int32_t, 3> opposite{};  ///< map reflector index opposite side[k]
};

/// Fills out (cleared first) with every map triangle whose sides are all in [min_side, max_side]
/// [m], each once; stops and returns false as soon as there are more than max_triangles.
bool enumerate_map_triangles(const ReflectorMap& map, double min_side, double max_side, size_t max_triangles,
                             std::vector<IndexedTriangle>& out);

class MapTriangleIndex {
 public:
  /// Indexes triangles with min_side <= every side <= max_side [m]; lookups accept a per-side
  /// error up to tolerance [m]. If more than max_triangles qualify, max_side shrinks until they fit.
  MapTriangleIndex(const ReflectorMap& map, double tolerance, double min_side, double max_side,
                   size_t max_triangles);

  /// Calls fn(const IndexedTriangle&) for every indexed triangle whose sorted sides are all within
  /// the tolerance of sides (ascending) [m].
  template <class Fn>
  void for_each_candidate(const std::array<double, 3>& sides, Fn&& fn) const {
    for_each_candidate(sides, {tolerance_, tolerance_, tolerance_}, std::forward<Fn>(fn));
  }
  /// The same with a tolerance per side (for sides[k], tolerances[k] [m]; any width, though
  /// one far above the index's own visits many cells).
  template <class Fn>
  void for_each_candidate(const std::array<double, 3>& sides, const std::array<double, 3>& tolerances,
                          Fn&& fn) const;

  size_t size() const { return triangles_.size(); }
  /// Every indexed triangle (ordered by cell, not by reflector).
  const std::vector<IndexedTriangle>& triangles() const { return triangles_; }
  double max_side() const { return max_side_; }  ///< [m] possibly reduced to meet max_triangles

 private:
  uint64_t key(int a, int b, int c) const;
  int cell(double side) const { return static_cast<int>(side / cell_size_); }

  double tolerance_;
  double cell_size_;
  double max_side_;
  std::vector<IndexedTriangle> triangles_;                             ///< sorted by cell key
  std::unordered_map<uint64_t, std::pair<uint32_t, uint32_t>> cells_;  ///< key -> [begin, end)
};

template <class Fn>
void MapTriangleIndex::for_each_candidate(const std::array<double, 3>& sides,
                                          const std::array<double, 3>& tolerances, Fn&& fn) const {
  if (sides[2] > max_side_ + tolerances[2]) return;
  // A cell is twice the index's tolerance wide: a side's interval at that tolerance touches at
  // most two cells, a wider one a few more.
  int lo[3], hi[3];
  for (int k = 0; k < 3; ++k) {
    lo[k] = cell(std::max(0.0, sides[k] - tolerances[k]));
    hi[k] = cell(sides[k] + tolerances[k]);
  }
  for (int a = lo[0]; a <= hi[0]; ++a) {
    for (int b = lo[1]; b <= hi[1]; ++b) {
      for (int c = lo[2]; c <= hi[2]; ++c) {
        const auto it = cells_.find(key(a, b, c));
        if (it == cells_.end()) continue;
        for (uint32_t t = it->second.first; t < it->second.second; ++t) {
          const IndexedTriangle& tri = triangles_[t];
          if (std::abs(tri.side[0] - sides[0]) <= tolerances[0] &&
              std::abs(tri.side[1] - sides[1]) <= tolerances[1] &&
              std::abs(tri.side[2] - sides[2]) <= tolerances[2]) {
            fn(tri);
          }
        }
      }
    }
  }
}

}  // namespace refloc
