#include "reflector_matcher/map_triangle_index.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

#include <set>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(MapTriangleIndex, IndexesEveryTriangleWithinTheSideLimits) {
  std::mt19937 rng(4);
  const ReflectorMap map = testing::random_map(30, 50, 50, 1.0, rng);
  const MapTriangleIndex index(map, 0.08, 0.3, 40.0, 1000000);
  size_t expected = 0;
  const auto& r = map.reflectors;
  for (size_t i = 0; i < r.size(); ++i)
    for (size_t j = i + 1; j < r.size(); ++j)
      for (size_t k = j + 1; k < r.size(); ++k) {
        const auto s = sorted_sides({r[i].map_p_center, r[j].map_p_center, r[k].map_p_center});
        if (s.side[0] >= 0.3 && s.side[2] <= 40.0) ++expected;
      }
  EXPECT_EQ(index.size(), expected);
  EXPECT_DOUBLE_EQ(index.max_side(), 40.0);
}

TEST(MapTriangleIndex, LookupFindsTheTriangleFromNoisySidesWithItsVertices) {
  std::mt19937 rng(5);
  const ReflectorMap map = testing::random_map(30, 50, 50, 1.0, rng);
  const MapTriangleIndex index(map, 0.08, 0.3, 40.0, 1000000);
  const auto& r = map.reflectors;
  const auto s = sorted_sides({r[3].map_p_center, r[7].map_p_center, r[11].map_p_center});
  if (s.side[2] > 40.0) GTEST_SKIP() << "random triangle too large";
  std::array<double, 3> noisy = {s.side[0] + 0.05, s.side[1] - 0.05, s.side[2] + 0.03};
  bool found = false;
  index.for_each_candidate(noisy, [&](const IndexedTriangle& t) {
    std::set<int> v(t.opposite.begin(), t.opposite.end());
    if (v == std::set<int>{3, 7, 11}) {
      found = true;
      const int ids[3] = {3, 7, 11};
      for (size_t k = 0; k < 3; ++k) EXPECT_EQ(t.opposite[k], ids[s.opposite[k]]);
    }
  });
  EXPECT_TRUE(found);
}

TEST(MapTriangleIndex, ShrinksTheSideLimitToStayUnderTheCap) {
  std::mt19937 rng(6);
  const ReflectorMap map = testing::random_map(60, 30, 30, 1.0, rng);
  const MapTriangleIndex index(map, 0.08, 0.3, 40.0, 5000);
  EXPECT_LE(index.size(), 5000u);
  EXPECT_LT(index.max_side(), 40.0);
  EXPECT_GT(index.size(), 0u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
