// Mission files: keys with their units and defaults, and errors naming file and key.

#include "mission_file.hpp"

#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

std::string write(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& path) {
  try {
    load_mission(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(MissionFile, ReadsWaypointsInDegreesAndEveryKey) {
  const Mission m =
      load_mission(write("full.json", R"({"waypoints": [{"x_m": 1.5, "y_m": -2, "theta_deg": 90},
      {"x_m": 0, "y_m": 0}], "xy_tolerance_m": 0.02, "heading_tolerance_deg": 1.0, "max_speed_m_s": 0.5,
      "timeout_s": 120, "localization_timeout_s": 30})"));
  ASSERT_EQ(m.waypoints.size(), 2u);
  EXPECT_DOUBLE_EQ(m.waypoints[0].x, 1.5);
  EXPECT_DOUBLE_EQ(m.waypoints[0].y, -2.0);
  EXPECT_DOUBLE_EQ(m.waypoints[0].theta, M_PI / 2);
  EXPECT_DOUBLE_EQ(m.waypoints[1].theta, 0.0);
  EXPECT_DOUBLE_EQ(m.xy_tolerance_m, 0.02);
  EXPECT_DOUBLE_EQ(m.heading_tolerance_rad, M_PI / 180.0);
  EXPECT_DOUBLE_EQ(m.max_speed_m_s, 0.5);
  EXPECT_DOUBLE_EQ(m.timeout_s, 120.0);
  EXPECT_DOUBLE_EQ(m.localization_timeout_s, 30.0);
}

TEST(MissionFile, DefaultsEqualTheStructsDefaults) {
  const Mission m = load_mission(write("minimal.json", R"({"waypoints": [{"x_m": 1, "y_m": 2}]})"));
  const Mission d;
  EXPECT_DOUBLE_EQ(m.xy_tolerance_m, d.xy_tolerance_m);
  EXPECT_DOUBLE_EQ(m.heading_tolerance_rad, d.heading_tolerance_rad);
  EXPECT_DOUBLE_EQ(m.max_speed_m_s, d.max_speed_m_s);
  EXPECT_DOUBLE_EQ(m.timeout_s, d.timeout_s);
  EXPECT_DOUBLE_EQ(m.localization_timeout_s, d.localization_timeout_s);
}

TEST(MissionFile, DeployedMissionsLoad) {
  for (const char* f :
       {"/deploy/config/mission_demo.json", "/tests/ops/data/restart_mission.json",
        "/tests/ops/data/restart_kill_mission.json", "/tests/ops/data/multihost_mission.json"}) {
    EXPECT_GE(load_mission(std::string(REFLOC_SOURCE_DIR) + f).waypoints.size(), 2u) << f;
  }
}

TEST(MissionFile, ErrorsNameFileAndKey) {
  const auto empty = write("empty.json", R"({"waypoints": []})");
  EXPECT_THAT(error_of(empty), HasSubstr(empty + ": /waypoints: expected at least one waypoint"));
  const auto no_y = write("no_y.json", R"({"waypoints": [{"x_m": 1}]})");
  EXPECT_THAT(error_of(no_y), HasSubstr(no_y + ": /waypoints/0/y_m"));
  const auto fast = write("fast.json", R"({"waypoints": [{"x_m": 1, "y_m": 1}], "max_speed_m_s": 9})");
  EXPECT_THAT(error_of(fast), HasSubstr(fast + ": /max_speed_m_s"));
  const auto typo = write("typo.json", R"({"waypoints": [{"x_m": 1, "y_m": 1}], "timeout": 9})");
  EXPECT_THAT(error_of(typo), HasSubstr("timeout"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
