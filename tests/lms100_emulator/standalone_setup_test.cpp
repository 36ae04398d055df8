#include "lms100_emulator/standalone_setup.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::string write_file(const std::string& name, const std::string& text) {
  const std::filesystem::path dir = std::filesystem::path(REFLOC_BINARY_DIR) / "standalone_setup_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / name).string();
  std::ofstream(path) << text;
  return path;
}

std::string error_of(const std::string& config_path, const EmulatorOverrides& o) {
  try {
    build_standalone_setup(config_path, o);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(StandaloneSetup, NoFileAndNoOptionsIsTheTestPatternAtFactoryDefaults) {
  const StandaloneSetup s = build_standalone_setup("", {});
  EXPECT_TRUE(s.world_path.empty());
  EXPECT_EQ(s.emulator.port, 2111);
  EXPECT_EQ(s.emulator.device.scan_frequency_1e2hz, 5000u);
  EXPECT_EQ(describe_scan_source(s), "no world given: sending the built-in test pattern");
}

TEST(StandaloneSetup, OptionsOverrideTheFile) {
  const std::string path = write_file("override.json", R"({"port": 3000, "spin_up_s": 1.0,
      "faults": {"junk_bytes_between_telegrams": 4}})");
  EmulatorOverrides o;
  o.port = 0;
  o.frequency_hz = 25;
  o.resolution_deg = 0.25;
  o.junk = 9;
  o.refuse_first_write = true;
  const StandaloneSetup s = build_standalone_setup(path, o);
  EXPECT_EQ(s.emulator.port, 0);
  EXPECT_DOUBLE_EQ(s.emulator.device.spin_up_s, 1.0);  // not overridden: the file's
  EXPECT_EQ(s.emulator.device.scan_frequency_1e2hz, 2500u);
  EXPECT_EQ(s.emulator.device.angular_resolution_1e4deg, 2500u);
  EXPECT_EQ(s.emulator.faults.junk_bytes_between_telegrams, 9);
  EXPECT_TRUE(s.emulator.refuse_first_write_after_power_up);
}

TEST(StandaloneSetup, FiftyHertzAtQuarterDegreeIsRefused) {
  EmulatorOverrides o;
  o.frequency_hz = 50;
  o.resolution_deg = 0.25;
  EXPECT_EQ(error_of("", o),
            "--frequency/--resolution: an LMS100 scans at 25 Hz (0.25 or 0.5 deg) or 50 Hz (0.5 deg)");
}

TEST(StandaloneSetup, PoseWithoutWorldIsRefused) {
  EmulatorOverrides o;
  o.pose = "1,2,0";
  EXPECT_EQ(error_of("", o), "--pose needs --world (or world_file in the config)");
}

TEST(StandaloneSetup, WorldFileIsRelativeToTheConfigAndPoseComesFromIt) {
  const std::string path =
      write_file("with_world.json", R"({"world_file": "hall.json", "map_T_laser": "10,3,1.5"})");
  const StandaloneSetup s = build_standalone_setup(path, {});
  EXPECT_EQ(s.world_path, (std::filesystem::path(path).parent_path() / "hall.json").string());
  EXPECT_DOUBLE_EQ(s.map_T_laser.x, 10.0);
  EXPECT_DOUBLE_EQ(s.map_T_laser.theta, 1.5);
  EmulatorOverrides o;
  o.world_path = "other.json";
  o.pose = "1,2,0.5";
  const StandaloneSetup s2 = build_standalone_setup(path, o);
  EXPECT_EQ(s2.world_path, "other.json");
  EXPECT_DOUBLE_EQ(s2.map_T_laser.y, 2.0);
}

TEST(StandaloneSetup, BadPoseTextNamesTheOption) {
  EmulatorOverrides o;
  o.world_path = "w.json";
  o.pose = "1,2";
  EXPECT_EQ(error_of("", o), "--pose: expected x,y,theta [m, m, rad], got '1,2'");
  EXPECT_THROW(parse_pose_text("1,2,3,", "x"), ConfigError);
  EXPECT_DOUBLE_EQ(parse_pose_text(" 1.5,-2,0.25 ", "x").y, -2.0);
}

TEST(StandaloneSetup, UnknownKeyInTheFileIsRefused) {
  const std::string path = write_file("unknown.json", R"({"prot": 2111})");
  EXPECT_NE(error_of(path, {}).find("prot"), std::string::npos);
}

TEST(StandaloneSetup, HeartbeatCountersCarryTheStatsByName) {
  Lms100EmulatorStats stats;
  stats.clients_accepted = 2;
  stats.scans_dropped = 5;
  const auto counters = heartbeat_counters(stats);
  ASSERT_EQ(counters.size(), 5u);
  EXPECT_STREQ(counters[0].first, "clients_accepted");
  EXPECT_EQ(counters[0].second, 2);
  EXPECT_STREQ(counters[3].first, "scans_dropped");
  EXPECT_EQ(counters[3].second, 5);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
