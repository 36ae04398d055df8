// The refloc-survey binary, subcommand static, on a small LCM log of rendered scans: the map it
// writes (format 2, surveyed, covariances), the progress lines when stderr is not a terminal,
// and its exit codes (2 bad file, 64 usage, 1 too few reflectors).

#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"
#include "rendered_static_survey.hpp"
#include "tests/tools/refloc-log/lcm_log_fixture.hpp"
#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const std::string kTool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-survey";

// count rendered scans of the demo hall with the robot at map_T_robot, as lms100_driver logs them.
std::string write_scan_log(const std::string& name, const Pose2& map_T_robot, int count) {
  const std::string path = testing::temp_path(name);
  const sim::World world = sim::load_world(testing::kConfigDir + "world_demo.json");
  const RobotConfig robot = load_robot_config(testing::kConfigDir + "robot.json");
  sim::ScanRenderer renderer(sim::ScanRenderConfig{});
  std::mt19937_64 rng(21);
  testing::LcmLogWriter log(path);
  LaserScan scan;
  for (int i = 0; i < count; ++i) {
    const int64_t utime = 1700000000000000 + i * 20000;
    renderer.render(world, map_T_robot * robot.robot_T_laser, utime, rng, scan);
    scan.scan_counter = static_cast<uint32_t>(i);
    log.write("LMS100_SCAN", utime, to_lcm(scan));
  }
  return path;
}

TEST(StaticSurveyCli, LogOfTwentyScansGivesASurveyedMapWithCovariances) {
  const std::string log = write_scan_log("static.lcmlog", Pose2{2.0, 2.0, 1.5}, 20);
  const std::string out = testing::temp_path("static_map.json");
  std::filesystem::remove(out);
  const auto r = testing::run_command(kTool + " static --log " + log + " --scans 20 --pose 2,2,1.5 --out " +
                                      out + " --map-id west_end --range-bias-mm 0 --range-bias-sigma-mm 0");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("20 scans used of 20 on LMS100_SCAN (0 refused"));
  EXPECT_THAT(r.output, HasSubstr("scans 100 % (20/20)"));  // a line every 10 %: not a terminal
  EXPECT_THAT(r.output, HasSubstr("map written: " + out));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("range bias not stated")));
  const ReflectorMap map = load_reflector_map(out);
  EXPECT_EQ(map.info.source, "surveyed");
  EXPECT_EQ(map.info.map_id, "west_end");
  EXPECT_EQ(map.info.version, 1);
  ASSERT_GE(map.reflectors.size(), 5u);
  const ReflectorMap truth = load_reflector_map(testing::kConfigDir + "map_demo.json");
  for (const MapReflector& r : map.reflectors) {
    ASSERT_TRUE(r.map_cov_center.has_value());
    double nearest = 1e9;
    for (const MapReflector& t : truth.reflectors)
      nearest = std::min(nearest, (r.map_p_center - t.map_p_center).norm());
    EXPECT_LT(nearest, 0.015) << "surveyed id " << r.id;
  }
}

TEST(StaticSurveyCli, ExitCodesAndWarnings) {
  const std::string log = write_scan_log("short.lcmlog", Pose2{2.0, 2.0, 1.5}, 5);
  const std::string out = testing::temp_path("map.json");
  std::filesystem::remove(out);
  // Fewer scans than asked: a warning; no bias stated: a warning; the map is still written.
  auto r = testing::run_command(kTool + " static --log " + log + " --scans 10 --pose 2,2,1.5 --out " + out);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("warning: 5 scans of the 10 asked for"));
  EXPECT_THAT(r.output, HasSubstr("warning: range bias not stated: 0 +- 30 mm assumed"));
  r = testing::run_command(kTool + " static --log " + log + " --out " + out);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(out + ": exists; give --force to replace it"));
  std::ofstream(testing::temp_path("not_a_log")) << "hello";
  r = testing::run_command(kTool + " static --log " + testing::temp_path("not_a_log") + " --out " + out +
                           "2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = testing::run_command(kTool + " static --log " + log + " --robot /nonexistent.json --out " + out + "3");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = testing::run_command(kTool + " static --log " + log);
  EXPECT_EQ(r.exit_code, 64) << r.output;
  r = testing::run_command(kTool + " static --log " + log + " --out x --pose 1,2");
  EXPECT_EQ(r.exit_code, 64) << r.output;
  // Facing the east wall from close by: its 3 reflectors lie on one line; written, with a warning.
  const std::string wall = write_scan_log("wall.lcmlog", Pose2{19.2, 5.5, 0.0}, 5);
  r = testing::run_command(kTool + " static --log " + wall + " --scans 5 --out " + out + "4");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("all 3 reflectors lie within"));
  EXPECT_THAT(r.output, HasSubstr("the pose is not observable from them alone"));
  // An extractor that sees nothing (threshold above every RSSI): no reflector, nothing written.
  const std::string blind = testing::temp_path("blind_extractor.json");
  std::ofstream(blind) << R"({"energy_threshold_8bit": 255})";
  r = testing::run_command(kTool + " static --log " + wall + " --scans 5 --extractor-config " + blind +
                           " --out " + out + "5");
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_THAT(r.output, HasSubstr("0 reflectors seen in 80 % of the scans; a map needs 3, not written"));
  EXPECT_FALSE(std::filesystem::exists(out + "5"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
