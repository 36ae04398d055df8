#include "world_renderer/world_occluders.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(WorldOccluders, DemoHallGivesItsWallAndFourObstaclesAsClosedPolylinesAndNoDistractor) {
  const World world = load_world(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json");
  const std::vector<MapOccluder> occluders = world_occluders(world);
  // The hall, two racks, two pillars; the 7 tape and metal distractors are no occluders.
  ASSERT_EQ(occluders.size(), 5u);
  size_t segments = 0;
  for (const MapOccluder& o : occluders) {
    EXPECT_TRUE(o.closed);
    EXPECT_EQ(o.map_points.size(), 4u);
    segments += o.map_points.size();
  }
  EXPECT_EQ(segments, 20u);
  EXPECT_EQ(occluders[0].map_points[2], Eigen::Vector2d(20, 12));    // the hall's corners, in order
  EXPECT_EQ(occluders[1].map_points[0], Eigen::Vector2d(5.0, 5.2));  // rack 1
}

TEST(WorldOccluders, OpenPolylinesStayOpenAndADistractorBetweenWallsSplitsNothingItShouldNot) {
  World world;
  add_polyline(world, {{0, 0}, {5, 0}, {5, 5}}, false, SurfaceKind::kDiffuse, 0.5);
  add_polyline(world, {{1, 1}, {2, 1}}, false, SurfaceKind::kReflectiveTape, 0.8);
  add_polyline(world, {{7, 0}, {8, 0}, {8, 1}}, true, SurfaceKind::kDiffuse, 0.3);
  add_polyline(world, {{9, 9}, {9, 10}}, false, SurfaceKind::kMetal, 0.05);
  const std::vector<MapOccluder> occluders = world_occluders(world);
  ASSERT_EQ(occluders.size(), 2u);
  EXPECT_FALSE(occluders[0].closed);
  EXPECT_EQ(occluders[0].map_points.size(), 3u);
  EXPECT_TRUE(occluders[1].closed);
  EXPECT_EQ(occluders[1].map_points.size(), 3u);
  EXPECT_TRUE(world_occluders(World{}).empty());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
