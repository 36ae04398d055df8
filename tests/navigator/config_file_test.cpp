#include "common/json_config.hpp"
#include "navigator/navigator_config_file.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

void expect_same_limits(const ProfileLimits& a, const ProfileLimits& b) {
  EXPECT_EQ(a.max_speed, b.max_speed);
  EXPECT_EQ(a.max_accel, b.max_accel);
  EXPECT_EQ(a.brake_fraction, b.brake_fraction);
  EXPECT_EQ(a.creep_speed, b.creep_speed);
  EXPECT_EQ(a.gain, b.gain);
}

TEST(NavigatorConfigFile, DeployedFileEqualsTheCodeDefaults) {
  const NavigatorServiceConfig c =
      load_navigator_service_config(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/navigator.json");
  const NavigatorServiceConfig d;
  expect_same_limits(c.navigator.translation, d.navigator.translation);
  EXPECT_EQ(c.navigator.translation.creep_distance, d.navigator.translation.creep_distance);
  expect_same_limits(c.navigator.rotation, d.navigator.rotation);
  // 2.8648 deg in the file, 0.05 rad in the code.
  EXPECT_NEAR(c.navigator.rotation.creep_distance, d.navigator.rotation.creep_distance, 1e-5);
  EXPECT_EQ(c.navigator.pose_timeout, d.navigator.pose_timeout);
  EXPECT_EQ(c.navigator.settle_time, d.navigator.settle_time);
  EXPECT_EQ(c.navigator.progress_timeout, d.navigator.progress_timeout);
  EXPECT_EQ(c.navigator.default_xy_tolerance, d.navigator.default_xy_tolerance);
  EXPECT_DOUBLE_EQ(c.navigator.default_heading_tolerance, d.navigator.default_heading_tolerance);
  EXPECT_EQ(c.navigator.drive_on_degraded_pose, d.navigator.drive_on_degraded_pose);
  EXPECT_EQ(c.control_rate, d.control_rate);
  EXPECT_EQ(c.status_rate, d.status_rate);
  EXPECT_EQ(c.goal_channel, d.goal_channel);
  EXPECT_EQ(c.pose_channel, d.pose_channel);
  EXPECT_EQ(c.command_channel, d.command_channel);
  EXPECT_EQ(c.status_channel, d.status_channel);
  EXPECT_NEAR(c.navigator.default_heading_tolerance, 0.5 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.navigator.pose_timeout, 0.2);
  EXPECT_DOUBLE_EQ(c.control_rate, 50.0);
}

TEST(NavigatorConfigFile, EmptyChannelIsRefused) {
  const JsonConfig file(nlohmann::json{{"command_channel", ""}}, "navigator.json");
  EXPECT_THROW(parse_navigator_service_config(file), ConfigError);
}

TEST(NavigatorConfigFile, RotationLimitIsNamedWithItsSection) {
  const JsonConfig file(nlohmann::json{{"navigator", {{"rotation", {{"max_speed_rad_s", 100.0}}}}}},
                        "navigator.json");
  try {
    parse_navigator_service_config(file);
    FAIL() << "accepted a yaw rate of 100 rad/s";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("navigator.json: /navigator/rotation/max_speed_rad_s:"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
