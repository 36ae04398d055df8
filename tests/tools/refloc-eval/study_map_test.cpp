#include "study_map.hpp"

#include "accuracy_study.hpp"
#include "common/robot_config.hpp"

#include "common/json_config.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>

#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

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

TEST(StudyMap, TheBoundIsTheWorldsWhateverIdsTheLoadedMapGivesItsReflectors) {
  // A surveyed map numbers its reflectors its own way; the CRLB used to pair the world's beams
  // with the loaded map's reflectors by id and printed nonsense (2452 mm) for such a map.
  const sim::World world = sim::load_world(kConfigDir + "paper_cell.json");
  ReflectorMap renumbered = load_reflector_map(world.map_file);
  for (MapReflector& r : renumbered.reflectors) r.id = 100 - r.id;
  const Pose2 robot_T_laser = load_robot_config(kConfigDir + "robot.json").robot_T_laser;
  const auto configs = [](PipelineMode mode) {
    return load_pipeline_configs(mode, kConfigDir + "reflector_extractor.json",
                                 kConfigDir + "reflector_matcher.json", kConfigDir + "pose_solver.json");
  };
  StudyConfig config;
  config.repeats = 1;
  std::vector<Pose2> poses = paper_table_poses();
  poses.resize(3);
  const StudyResult with_world_ids =
      run_study(world, load_reflector_map(world.map_file), robot_T_laser, configs(PipelineMode::kPaper),
                configs(PipelineMode::kDefault), poses, config, {});
  const StudyResult with_other_ids =
      run_study(world, renumbered, robot_T_laser, configs(PipelineMode::kPaper),
                configs(PipelineMode::kDefault), poses, config, {});
  ASSERT_EQ(with_world_ids.measurements.size(), with_other_ids.measurements.size());
  for (size_t i = 0; i < with_world_ids.measurements.size(); ++i) {
    ASSERT_TRUE(with_world_ids.measurements[i].has_crlb);
    EXPECT_DOUBLE_EQ(with_world_ids.measurements[i].crlb_var_xy, with_other_ids.measurements[i].crlb_var_xy);
  }
  EXPECT_LT(with_other_ids.default_mode.crlb_rmse_mm, 10.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
