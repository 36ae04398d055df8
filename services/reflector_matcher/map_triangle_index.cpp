#include "reflector_matcher/map_triangle_index.hpp"

#include "reflector_matcher/map_grid.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {
bool enumerate_map_triangles(const ReflectorMap& map, double min_side, double max_side, size_t max_triangles,
                             std::vector<IndexedTriangle>& out) {
  out.clear();
  const MapGrid grid(map, max_side);
  std::vector<int> near;
  const auto& r = map.reflectors;
  const double max2 = max_side * max_side, min2 = min_side * min_side;
  const auto fits = [&](int i, int j) {
    const double d2 =
        (r[static_cast<size_t>(i)].map_p_center - r[static_cast<size_t>(j)].map_p_center).squaredNorm();
    return d2 <= max2 && d2 >= min2;
  };
  for (int i = 0; i < static_cast<int>(r.size()); ++i) {
    near.clear();
    grid.query(r[static_cast<size_t>(i)].map_p_center, max_side, near);
    // Each triangle once: i is its lowest index.
    near.erase(std::remove_if(near.begin(), near.end(), [&](int j) { return j <= i || !fits(i, j); }),
               near.end());
    std::sort(near.begin(), near.end());
    for (size_t a = 0; a < near.size(); ++a) {
      for (size_t b = a + 1; b < near.size(); ++b) {
        const int j = near[a], k = near[b];
        if (!fits(j, k)) continue;
        const SortedSides s =
            sorted_sides({r[static_cast<size_t>(i)].map_p_center, r[static_cast<size_t>(j)].map_p_center,
                          r[static_cast<size_t>(k)].map_p_center});
        const int ids[3] = {i, j, k};
        IndexedTriangle t;
        for (int m = 0; m < 3; ++m) {
          t.side[static_cast<size_t>(m)] = static_cast<float>(s.side[static_cast<size_t>(m)]);
          t.opposite[static_cast<size_t>(m)] = ids[s.opposite[static_cast<size_t>(m)]];
        }
        out.push_back(t);
        if (out.size() > max_triangles) return false;
      }
    }
  }
  return true;
}

MapTriangleIndex::MapTriangleIndex(const ReflectorMap& map, double tolerance, double min_side,
                                   double max_side, size_t max_triangles)
    : tolerance_(tolerance), cell_size_(2.0 * tolerance), max_side_(max_side) {
  while (!enumerate_map_triangles(map, min_side, max_side_, max_triangles, triangles_) &&
         max_side_ > min_side) {
    max_side_ *= 0.8;
  }
  std::vector<std::pair<uint64_t, uint32_t>> keyed(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const auto& s = triangles_[t].side;
    keyed[t] = {key(cell(s[0]), cell(s[1]), cell(s[2])), static_cast<uint32_t>(t)};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<IndexedTriangle> sorted(triangles_.size());
  for (size_t t = 0; t < keyed.size(); ++t) sorted[t] = triangles_[keyed[t].second];
  triangles_.swap(sorted);
  for (size_t t = 0; t < keyed.size();) {
    size_t end = t;
    while (end < keyed.size() && keyed[end].first == keyed[t].first) ++end;
    cells_[keyed[t].first] = {static_cast<uint32_t>(t), static_cast<uint32_t>(end)};
    t = end;
  }
}

uint64_t MapTriangleIndex::key(int a, int b, int c) const {
  // 21 bits a cell coordinate: 2 million cells of 2 * tolerance, far beyond any side length.
  constexpr uint64_t kMask = (1u << 21) - 1;
  return (static_cast<uint64_t>(a) & kMask) | ((static_cast<uint64_t>(b) & kMask) << 21) |
         ((static_cast<uint64_t>(c) & kMask) << 42);
}

}  // namespace refloc
