#include "robot_sim/sim_setup.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kDeployed = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/robot_sim.json";

TEST(SimSetup, DeployedConfigLoadsWithTheWorldNextToIt) {
  const SimSetup s = load_sim_setup(kDeployed, {});
  EXPECT_EQ(s.world_path, (std::filesystem::path(kDeployed).parent_path() / "world_demo.json").string());
  EXPECT_EQ(s.emulator.port, 2111);
  EXPECT_DOUBLE_EQ(s.encoder_rate, 100.0);
  EXPECT_EQ(s.command_channel, "CMD_VEL");
  EXPECT_EQ(s.plant.encoder_start_ticks, 2147000000);
}

TEST(SimSetup, OverridesBeatTheFile) {
  SimOverrides o;
  o.world_path = "other.json";
  o.port = 0;
  o.sensor_bind_address = "0.0.0.0";
  const SimSetup s = load_sim_setup(kDeployed, o);
  EXPECT_EQ(s.world_path, "other.json");
  EXPECT_EQ(s.emulator.port, 0);
  EXPECT_EQ(s.emulator.bind_address, "0.0.0.0");
}

TEST(SimSetup, NoLaserClearsTheWorld) {
  SimOverrides o;
  o.world_path = "other.json";
  o.no_laser = true;
  EXPECT_TRUE(load_sim_setup(kDeployed, o).world_path.empty());
}

TEST(SimSetup, NoFileGivesTheDefaultsWithoutALaser) {
  const SimSetup s = load_sim_setup("", {});
  EXPECT_TRUE(s.world_path.empty());
  EXPECT_DOUBLE_EQ(s.ground_truth_rate, 100.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
