// refloc-survey drive --live on a real udpm bus (private network namespace,
// tests/tools/run_in_netns.sh): this test publishes the rendered lower-aisle drive
// (drive_rendered.hpp) message by message while the binary records it; the map it writes must
// equal the map the binary makes from the same messages written as a log, and its recorded log
// must hold every message. Also: no scan on the bus is a clear failure with no map.

#include "drive_rendered.hpp"
#include "refloc-log/lcm_log_fixture.hpp"
#include "tests/tools/child_process.hpp"

#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <lcm/lcm-cpp.hpp>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

namespace refloc {
namespace {

const std::string kSurvey = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-survey";
const std::string kUrl = "udpm://239.255.76.67:7667?ttl=0";

std::string file_text(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

/// The exit code once the child ends by itself (SIGTERM only after timeout: it would end a
/// recording early).
int wait_exit(testing::ChildProcess& child, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (child.running() && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  return child.stop();
}

std::string start_pose() {
  const Pose2& p = testing::lower_aisle_drive().true_map_T_robot.front();
  return fmt::format("{},{},{}", p.x, p.y, p.theta);
}

/// Calls f(channel, message) for the drive's messages in the order the bus carried them.
template <class F>
void for_each_drive_message(F&& f) {
  const testing::RenderedDrive& d = testing::lower_aisle_drive();
  size_t scan = 0, odometry = 0;
  for (bool is_scan : d.raw_order_is_scan) {
    if (is_scan)
      f("LMS100_SCAN", to_lcm(d.raw_scans[scan++]));
    else
      f("ODOMETRY", testing::odometry_message(d.raw_odometry[odometry++]));
  }
}

TEST(SurveyDriveLive, TheMapFromTheBusEqualsTheMapFromTheSameDriveAsALog) {
  const std::string reference_log = testing::temp_path("reference.lcmlog");
  {
    testing::LcmLogWriter log(reference_log);
    for_each_drive_message(
        [&](const std::string& channel, const auto& m) { log.write(channel, m.utime, m); });
  }
  const std::string recorded = testing::temp_path("recorded.lcmlog");
  const std::string live_map = testing::temp_path("live.json");
  const std::string output = testing::temp_path("live.txt");
  for (const std::string& f : {recorded, live_map}) std::filesystem::remove(f);
  testing::ChildProcess survey({kSurvey, "drive", "--live", "--lcm-url", kUrl, "--record", recorded,
                                "--timeout-s", "2", "--out", live_map, "--start-pose", start_pose()},
                               output);
  // The drive is published only once the binary listens: a message it misses would make the maps differ.
  for (int i = 0; i < 400 && survey.running() && file_text(output).find("recording") == std::string::npos;
       ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  ASSERT_NE(file_text(output).find("recording LMS100_SCAN and ODOMETRY"), std::string::npos)
      << file_text(output);
  lcm::LCM bus(kUrl);
  ASSERT_TRUE(bus.good());
  int scans = 0, odometry = 0;
  for_each_drive_message([&](const std::string& channel, const auto& m) {
    bus.publish(channel, &m);
    ++(channel == "LMS100_SCAN" ? scans : odometry);
    // Paced (the drive's 14 s in ~3 s): loopback multicast into the default receive buffer.
    std::this_thread::sleep_for(std::chrono::milliseconds(channel == "LMS100_SCAN" ? 10 : 2));
  });
  ASSERT_EQ(wait_exit(survey, std::chrono::seconds(120)), 0) << file_text(output);
  EXPECT_NE(
      file_text(output).find(fmt::format("recorded {} scans and {} odometry messages", scans, odometry)),
      std::string::npos)
      << file_text(output);
  EXPECT_NE(file_text(output).find("no scan within --timeout-s"), std::string::npos) << file_text(output);

  const std::string log_map = testing::temp_path("log.json");
  std::filesystem::remove(log_map);
  testing::ChildProcess from_log(
      {kSurvey, "drive", "--log", reference_log, "--out", log_map, "--start-pose", start_pose()},
      testing::temp_path("log.txt"));
  ASSERT_EQ(wait_exit(from_log, std::chrono::seconds(120)), 0) << file_text(testing::temp_path("log.txt"));
  const ReflectorMap a = load_reflector_map(live_map), b = load_reflector_map(log_map);
  ASSERT_GE(a.reflectors.size(), 5u);
  ASSERT_EQ(a.reflectors.size(), b.reflectors.size());
  for (size_t k = 0; k < a.reflectors.size(); ++k) {
    EXPECT_EQ(a.reflectors[k].id, b.reflectors[k].id);
    EXPECT_NEAR((a.reflectors[k].map_p_center - b.reflectors[k].map_p_center).norm(), 0.0, 1e-9) << k;
  }
}

TEST(SurveyDriveLive, NoScanOnTheBusIsAFailureWithoutAMap) {
  const std::string map = testing::temp_path("never.json");
  const std::string output = testing::temp_path("silent.txt");
  std::filesystem::remove(map);
  std::filesystem::remove(testing::temp_path("never.lcmlog"));
  testing::ChildProcess survey(
      {kSurvey, "drive", "--live", "--lcm-url", kUrl, "--timeout-s", "0.5", "--out", map}, output);
  EXPECT_EQ(wait_exit(survey, std::chrono::seconds(30)), 2) << file_text(output);
  EXPECT_NE(file_text(output).find("no scan on LMS100_SCAN (no scan within --timeout-s): nothing to survey"),
            std::string::npos)
      << file_text(output);
  EXPECT_FALSE(std::filesystem::exists(map));
}

TEST(SurveyDriveLive, LogAndLiveTogetherOrNeitherAreUsageErrors) {
  const std::string output = testing::temp_path("usage.txt");
  testing::ChildProcess neither({kSurvey, "drive", "--out", testing::temp_path("x.json")}, output);
  EXPECT_EQ(wait_exit(neither, std::chrono::seconds(30)), 64) << file_text(output);
  EXPECT_NE(file_text(output).find("--log F or --live"), std::string::npos) << file_text(output);
  testing::ChildProcess both(
      {kSurvey, "drive", "--log", "x.lcmlog", "--live", "--out", testing::temp_path("x.json")}, output);
  EXPECT_EQ(wait_exit(both, std::chrono::seconds(30)), 64) << file_text(output);
}

}  // namespace
}  // namespace refloc
