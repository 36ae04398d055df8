// find_map_self_similarity: the symmetric hall looks like itself turned half round (all 12);
// in the demo hall one move puts 6 of 24 onto others (reflectors evenly spaced along walls).

#include "reflector_matcher/map_self_similarity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(MapSelfSimilarity, TheSymmetricHallLooksWhollyLikeItselfTheDemoHallAQuarter) {
  const ReflectorMap symmetric = load_reflector_map(REFLOC_SOURCE_DIR "/deploy/config/map_symmetric.json");
  const MapSelfSimilarity s = find_map_self_similarity(symmetric);
  std::printf("symmetric hall: %d of %zu reflectors onto others by (%.2f, %.2f, %.1f deg)\n",
              s.reflectors_matched, symmetric.reflectors.size(), s.move.x, s.move.y,
              s.move.theta * 180.0 / M_PI);
  EXPECT_EQ(s.reflectors_matched, static_cast<int>(symmetric.reflectors.size()));

  const ReflectorMap demo = load_reflector_map(REFLOC_SOURCE_DIR "/deploy/config/map_demo_v2.json");
  const MapSelfSimilarity d = find_map_self_similarity(demo);
  std::printf("demo hall: %d of %zu\n", d.reflectors_matched, demo.reflectors.size());
  EXPECT_EQ(d.reflectors_matched, 6);
}

TEST(MapSelfSimilarity, FewerThanThreeReflectorsHaveNone) {
  ReflectorMap map;
  map.reflectors = {{1, {0.0, 0.0}, 0.06, "", {}}, {2, {3.0, 0.0}, 0.06, "", {}}};
  EXPECT_EQ(find_map_self_similarity(map).reflectors_matched, 0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
