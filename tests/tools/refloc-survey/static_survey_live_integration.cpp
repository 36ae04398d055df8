// refloc-survey static live: the binary subscribes to LMS100_SCAN on a real udpm bus (private
// network namespace, tests/tools/run_in_netns.sh) while this test publishes rendered scans of the
// demo hall at the LMS100's 50 Hz; and gives up with exit 2 when no scan comes.

#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"
#include "rendered_static_survey.hpp"
#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

namespace refloc {
namespace {

const std::string kTool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-survey";
const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

std::string temp_file(const std::string& name) {
  return ::testing::TempDir() + "refloc_static_live_" + std::to_string(::getpid()) + "_" + name;
}

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(StaticSurveyLive, SurveysScansFromTheBus) {
  const sim::World world = sim::load_world(testing::kConfigDir + "world_demo.json");
  const RobotConfig robot = load_robot_config(testing::kConfigDir + "robot.json");
  const std::string out = temp_file("map.json");
  const std::string log = temp_file("out.txt");
  std::filesystem::remove(out);
  testing::ChildProcess survey({kTool, "static", "--lcm-url", kUrl, "--scans", "20", "--pose", "2,2,1.5",
                                "--range-bias-sigma-mm", "0", "--timeout-s", "5", "--out", out},
                               log);
  lcm::LCM bus(kUrl);
  ASSERT_TRUE(bus.good());
  sim::ScanRenderer renderer(sim::ScanRenderConfig{});
  std::mt19937_64 rng(8);
  LaserScan scan;
  // Published until the survey has its 20 (it may join late: a bound, not a timing check).
  for (int i = 0; i < 1500 && survey.running(); ++i) {
    const int64_t utime = std::chrono::duration_cast<std::chrono::microseconds>(
                              std::chrono::system_clock::now().time_since_epoch())
                              .count();
    renderer.render(world, Pose2{2.0, 2.0, 1.5} * robot.robot_T_laser, utime, rng, scan);
    scan.scan_counter = static_cast<uint32_t>(i);
    laser_scan_t message = to_lcm(scan);
    bus.publish("LMS100_SCAN", &message);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const int exit_code = survey.stop(std::chrono::milliseconds(10000));
  ASSERT_EQ(exit_code, 0) << file_text(log);
  EXPECT_NE(file_text(log).find("20 scans used of"), std::string::npos) << file_text(log);
  const ReflectorMap map = load_reflector_map(out);
  EXPECT_EQ(map.info.source, "surveyed");
  EXPECT_GE(map.reflectors.size(), 5u);
}

TEST(StaticSurveyLive, NoScanOnTheBusIsExitTwoAfterTheTimeout) {
  const std::string log = temp_file("silent.txt");
  testing::ChildProcess survey({kTool, "static", "--lcm-url", kUrl, "--scans", "5", "--timeout-s", "0.5",
                                "--out", temp_file("never.json")},
                               log);
  for (int i = 0; i < 500 && survey.running(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(survey.stop(), 2) << file_text(log);
  EXPECT_NE(file_text(log).find("the bus: no usable scan on LMS100_SCAN"), std::string::npos)
      << file_text(log);
  EXPECT_FALSE(std::filesystem::exists(temp_file("never.json")));
}

}  // namespace
}  // namespace refloc
