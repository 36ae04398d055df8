#include "reflector_matcher/occluder_grid.hpp"
#include "reflector_matcher/reflector_visibility.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

MapOccluder polyline(std::vector<Eigen::Vector2d> points, bool closed = false) {
  MapOccluder o;
  o.map_points = std::move(points);
  o.closed = closed;
  return o;
}

MapReflector reflector_at(double x, double y, double radius = 0.06) {
  MapReflector r;
  r.map_p_center = {x, y};
  r.radius = radius;
  return r;
}

TEST(OccluderGrid, ALineThroughAWallIsBlockedOneEndingOnItOrBesideItIsNot) {
  const OccluderGrid grid({polyline({{0, 0}, {10, 0}})});
  EXPECT_EQ(grid.segment_count(), 1u);
  EXPECT_TRUE(grid.blocks({5, 2}, {5, -2}));
  EXPECT_TRUE(grid.blocks({5, -2}, {5, 2}));
  EXPECT_FALSE(grid.blocks({5, 2}, {5, 0}));     // ends on the wall: a reflector mounted on it
  EXPECT_FALSE(grid.blocks({5, 2}, {5, 0.01}));  // stops short
  EXPECT_FALSE(grid.blocks({11, 2}, {11, -2}));  // passes the wall's end
  EXPECT_TRUE(grid.blocks({10, 2}, {10, -2}));   // through its end point: a corner hides
  EXPECT_FALSE(grid.blocks({1, 1}, {9, 1}));     // parallel
  EXPECT_FALSE(grid.blocks({5, 2}, {5, 2}));     // no line at all
}

TEST(OccluderGrid, ClosedPolylinesGetTheirLastSegmentAndLinesFromFarOutsideTheGridAreWalked) {
  const OccluderGrid grid({polyline({{0, 0}, {4, 0}, {4, 2}, {0, 2}}, true)});
  EXPECT_EQ(grid.segment_count(), 4u);
  EXPECT_TRUE(grid.blocks({-1, 1}, {2, 1}));  // the closing segment x = 0
  EXPECT_TRUE(grid.blocks({-1000, 1}, {1000, 1.5}));
  EXPECT_FALSE(grid.blocks({-1000, 3}, {1000, 3}));
  EXPECT_FALSE(OccluderGrid({polyline({{0, 0}, {4, 0}, {4, 2}, {0, 2}})}).blocks({-1, 1}, {2, 1}));
  EXPECT_TRUE(OccluderGrid({}).empty());
  EXPECT_FALSE(OccluderGrid({}).blocks({0, 0}, {1, 1}));
}

TEST(OccluderGrid, AgreesWithTestingEverySegmentOnTwentyThousandRandomLines) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-5.0, 45.0), len(-3.0, 3.0);
  std::vector<MapOccluder> occluders;
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector2d a(u(rng), u(rng));
    // Axis-aligned ones put segments on cell edges, where a walk's rounding would show.
    const Eigen::Vector2d b = i % 3 == 0   ? Eigen::Vector2d(a.x(), a.y() + len(rng))
                              : i % 3 == 1 ? Eigen::Vector2d(std::round(a.x()), a.y() + len(rng))
                                           : a + Eigen::Vector2d(len(rng), len(rng));
    occluders.push_back(polyline({i % 3 == 1 ? Eigen::Vector2d(std::round(a.x()), a.y()) : a, b}));
  }
  const OccluderGrid grid(occluders);  // 2 m cells
  const OccluderGrid half_metre(occluders, 0.5);
  const OccluderGrid one_cell(occluders, 1e9);
  int blocked = 0, disagreements = 0;
  for (int i = 0; i < 20000; ++i) {
    Eigen::Vector2d p(u(rng), u(rng)), q(u(rng), u(rng));
    if (i % 4 == 0) q.x() = p.x();  // along a grid line now and then
    if (i % 4 == 1) p.y() = std::round(p.y()), q.y() = p.y();
    const bool truth = testing::crosses_occluder(occluders, p, q);
    blocked += truth;
    disagreements +=
        grid.blocks(p, q) != truth || half_metre.blocks(p, q) != truth || one_cell.blocks(p, q) != truth;
  }
  EXPECT_EQ(disagreements, 0);
  EXPECT_GT(blocked, 2000);  // both answers are well represented
  EXPECT_LT(blocked, 18000);
}

TEST(LineOfSight, BehindAWallIsBlockedInFrontClearAndAWallEndAcrossTheCylinderPartial) {
  const OccluderGrid wall({polyline({{0, 0}, {10, 0}})});
  const Eigen::Vector2d laser(5, 3);
  EXPECT_EQ(line_of_sight(wall, laser, reflector_at(5, -0.5)), LineOfSight::kBlocked);
  EXPECT_EQ(line_of_sight(wall, laser, reflector_at(5, 0.5)), LineOfSight::kClear);
  // Mounted on the wall (its back 4 cm from it), seen at a grazing 3 deg: clear.
  EXPECT_EQ(line_of_sight(wall, {1, 0.5}, reflector_at(9, 0.1)), LineOfSight::kClear);
  // The wall ends at x = 10: a reflector behind it whose centre is on the line of the end
  // shows the laser its far half.
  EXPECT_EQ(line_of_sight(wall, {10, 3}, reflector_at(10, -1)), LineOfSight::kPartial);
  EXPECT_EQ(line_of_sight(wall, {10, 3}, reflector_at(10.2, -1)), LineOfSight::kClear);
  EXPECT_EQ(line_of_sight(wall, {10, 3}, reflector_at(9.8, -1)), LineOfSight::kBlocked);
}

TEST(LineOfSight, TheCacheAnswersPerPositionAndNothingIsHiddenWithoutOccluders) {
  const OccluderGrid wall({polyline({{0, 0}, {10, 0}})});
  ReflectorMap map;
  map.reflectors = {reflector_at(5, -0.5), reflector_at(5, 0.5), reflector_at(10, -1)};
  std::vector<PredictedReflector> predicted(3);
  for (int i = 0; i < 3; ++i) predicted[static_cast<size_t>(i)].map_index = i;
  SightCache cache;
  cache.reset(&wall, {5, 3}, predicted.size());
  EXPECT_TRUE(cache.hidden(map, predicted, 0));
  EXPECT_FALSE(cache.clear(map, predicted, 0));
  EXPECT_FALSE(cache.hidden(map, predicted, 1));
  EXPECT_TRUE(cache.clear(map, predicted, 1));
  cache.reset(&wall, {10, 3}, predicted.size());  // the wall's end across reflector 2: partial
  EXPECT_FALSE(cache.hidden(map, predicted, 2));
  EXPECT_FALSE(cache.clear(map, predicted, 2));
  cache.reset(&wall, {5, -3}, predicted.size());
  EXPECT_TRUE(cache.clear(map, predicted, 0));
  EXPECT_TRUE(cache.hidden(map, predicted, 1));
  const OccluderGrid none({});
  for (const OccluderGrid* occluders : {&none, static_cast<const OccluderGrid*>(nullptr)}) {
    cache.reset(occluders, {5, 3}, predicted.size());
    EXPECT_FALSE(cache.hidden(map, predicted, 0));
    EXPECT_TRUE(cache.clear(map, predicted, 0));
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
