// robot.json (common/robot_config.hpp): the deployed file equals the code defaults,
// and mistakes in it are named by file and key.

#include "common/robot_config.hpp"
#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

TEST(RobotConfig, DeployedRobotFileEqualsTheCodeDefaults) {
  const RobotConfig robot = load_robot_config(kConfigDir + "robot.json");
  const RobotConfig defaults;
  EXPECT_EQ(robot.wheel_radius, defaults.wheel_radius);
  EXPECT_EQ(robot.half_wheelbase_lx, defaults.half_wheelbase_lx);
  EXPECT_EQ(robot.half_track_ly, defaults.half_track_ly);
  EXPECT_EQ(robot.encoder_ticks_per_rev, defaults.encoder_ticks_per_rev);
  EXPECT_EQ(robot.max_wheel_speed, defaults.max_wheel_speed);
  EXPECT_EQ(robot.max_wheel_accel, defaults.max_wheel_accel);
  EXPECT_EQ(robot.robot_T_laser.x, defaults.robot_T_laser.x);
  EXPECT_EQ(robot.robot_T_laser.y, defaults.robot_T_laser.y);
  EXPECT_EQ(robot.robot_T_laser.theta, defaults.robot_T_laser.theta);
  const OdometryNoise &n = robot.odometry_noise, &d = defaults.odometry_noise;
  EXPECT_EQ(n.translation_variance_per_m, d.translation_variance_per_m);
  EXPECT_EQ(n.heading_variance_per_m, d.heading_variance_per_m);
  EXPECT_EQ(n.heading_variance_per_rad, d.heading_variance_per_rad);
  EXPECT_EQ(n.translation_variance_per_rad, d.translation_variance_per_rad);
  // The values themselves, so a changed default is a visible decision.
  EXPECT_DOUBLE_EQ(robot.wheel_radius, 0.076);
  EXPECT_EQ(robot.encoder_ticks_per_rev, 16384);
  EXPECT_DOUBLE_EQ(robot.robot_T_laser.x, 0.30);
  EXPECT_DOUBLE_EQ(n.heading_variance_per_rad, 2.5e-4);
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
  const JsonConfig noise(nlohmann::json{{"odometry_noise", {{"translation_variance_m2_per_m", 2.0}}}},
                         "robot.json");
  try {
    parse_robot_config(noise);
    FAIL() << "accepted a variance of 2 m^2 per m";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("robot.json: /odometry_noise/translation_variance_m2_per_m:"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
