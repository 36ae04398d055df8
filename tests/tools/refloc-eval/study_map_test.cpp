#include "study_map.hpp"

#include "common/json_config.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace refloc {
namespace {

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

TEST(StudyMap, TheWorldsWallsTheMapFilesOrNoneAndTheDemoV2MapCarriesTheWorldsWalls) {
  const sim::World world = sim::load_world(kConfigDir + "world_demo.json");
  const ReflectorMap v1 = study_map(world, "", "map");
  EXPECT_EQ(v1.reflectors.size(), 24u);
  EXPECT_EQ(occluder_segment_count(v1.occluders), 0u);  // map_demo.json is format 1
  const ReflectorMap walls = study_map(world, "", "world");
  EXPECT_EQ(occluder_segment_count(walls.occluders), 20u);
  const ReflectorMap v2 = study_map(world, kConfigDir + "map_demo_v2.json", "map");
  ASSERT_EQ(v2.occluders.size(), walls.occluders.size());
  for (size_t i = 0; i < v2.occluders.size(); ++i) {
    EXPECT_EQ(v2.occluders[i].map_points, walls.occluders[i].map_points);
    EXPECT_EQ(v2.occluders[i].closed, walls.occluders[i].closed);
  }
  EXPECT_TRUE(study_map(world, kConfigDir + "map_demo_v2.json", "none").occluders.empty());
  EXPECT_THROW(study_map(world, "", "walls"), ConfigError);
}

}  // namespace
}  // namespace refloc
