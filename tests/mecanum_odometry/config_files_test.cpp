// The deployed config files load, and mistakes in them are named.

#include "common/json_config.hpp"
#include "common/robot_config.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace {

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

TEST(RobotConfig, DeployedRobotFileLoads) {
  const RobotConfig robot = load_robot_config(kConfigDir + "robot.json");
  EXPECT_DOUBLE_EQ(robot.wheel_radius, 0.076);
  EXPECT_DOUBLE_EQ(robot.half_wheelbase_lx, 0.25);
  EXPECT_DOUBLE_EQ(robot.half_track_ly, 0.22);
  EXPECT_EQ(robot.encoder_ticks_per_rev, 16384);
  EXPECT_DOUBLE_EQ(robot.robot_T_laser.x, 0.30);
}

TEST(RobotConfig, OutOfRangeAndUnknownKeysAreNamed) {
  const JsonConfig bad(nlohmann::json{{"wheel_radius_m", -3}}, "robot.json");
  try {
    parse_robot_config(bad);
    FAIL() << "accepted a negative radius";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.json: /wheel_radius_m:"), std::string::npos) << e.what();
  }
  const JsonConfig misspelt(nlohmann::json{{"laser_mount", {{"x", 0.3}}}}, "robot.json");
  parse_robot_config(misspelt);
  try {
    misspelt.reject_unknown_keys();
    FAIL() << "accepted /laser_mount/x";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/laser_mount/x: unknown key"), std::string::npos) << e.what();
  }
}

TEST(OdometryConfigFile, DeployedFileLoadsWithTheLibraryDefaults) {
  const JsonConfig file = JsonConfig::load_file(kConfigDir + "mecanum_odometry.json");
  const OdometryServiceConfig c = parse_odometry_service_config(file);
  file.reject_unknown_keys();
  const OdometryNoise defaults;
  EXPECT_DOUBLE_EQ(c.odometry.noise.translation_variance_per_m, defaults.translation_variance_per_m);
  EXPECT_DOUBLE_EQ(c.odometry.noise.heading_variance_per_rad, defaults.heading_variance_per_rad);
  EXPECT_EQ(c.input_channel, "WHEEL_ENCODERS");
}

}  // namespace
}  // namespace refloc
