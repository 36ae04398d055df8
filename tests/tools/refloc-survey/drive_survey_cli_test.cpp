// refloc-survey drive and compare as a user runs them: the rendered lower-aisle drive
// (drive_rendered.hpp) written as an LCM log with LCM's own writer (LMS100_SCAN, ODOMETRY in
// bus order), the binary run on it, the map file read back; bad inputs and usage errors.

#include "drive_rendered.hpp"
#include "refloc-log/lcm_log_fixture.hpp"
#include "run_command.hpp"

#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <filesystem>
#include <regex>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kSurvey = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-survey";

const std::string& drive_log() {
  static const std::string path = [] {
    const std::string p = testing::temp_path("drive.lcmlog");
    const testing::RenderedDrive& d = testing::lower_aisle_drive();
    testing::LcmLogWriter log(p);
    size_t scan = 0, odometry = 0;
    for (bool is_scan : d.raw_order_is_scan) {
      if (is_scan) {
        const LaserScan& s = d.raw_scans[scan++];
        log.write("LMS100_SCAN", s.utime + 16000, to_lcm(s));
      } else {
        const OdometrySample& o = d.raw_odometry[odometry++];
        log.write("ODOMETRY", o.utime + 500, testing::odometry_message(o));
      }
    }
    for (size_t k = 0; k < d.scans.size(); ++k) {  // the truth at every scan, as robot_sim publishes it
      pose2d_t truth{};
      truth.utime = d.scans[k].utime;
      truth.x = d.true_map_T_robot[k].x;
      truth.y = d.true_map_T_robot[k].y;
      truth.theta = d.true_map_T_robot[k].theta;
      log.write("GROUND_TRUTH", truth.utime, truth);
    }
    return p;
  }();
  return path;
}

std::string start_pose() {
  const Pose2& p = testing::lower_aisle_drive().true_map_T_robot.front();
  return fmt::format("{},{},{}", p.x, p.y, p.theta);
}

TEST(SurveyDriveCli, WritesAFormat2MapWithCovariancesOccludersAndAReport) {
  const std::string map = testing::temp_path("map.json");
  const std::string report = testing::temp_path("report");
  const auto r =
      testing::run_command(fmt::format("{} drive --log {} --out {} --start-pose {} --report {} --truth {} "
                                       "--truth-channel GROUND_TRUTH",
                                       kSurvey, drive_log(), map, start_pose(), report, testing::kDemoMap));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::smatch bias;
  ASSERT_TRUE(std::regex_search(
      r.output, bias,
      std::regex(R"(range bias \(measured - true range\): ([-+0-9.]+) mm, sigma ([0-9.]+) mm)")))
      << r.output;
  // The rendered LMS100's offset, within 3 of the survey's own sigmas (14 s, 7 reflectors: ~2 mm).
  EXPECT_NEAR(std::stod(bias[1]), 20.0, 3.0 * std::stod(bias[2]));
  EXPECT_LT(std::stod(bias[2]), 2.5);
  EXPECT_NE(r.output.find("map entries without a real reflector: 0"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("detections at the true poses"), std::string::npos) << r.output;
  const ReflectorMap m = load_reflector_map(map);
  EXPECT_EQ(m.info.format, 2);
  EXPECT_EQ(m.info.source, "surveyed");
  EXPECT_EQ(m.info.version, 1);
  EXPECT_GE(m.reflectors.size(), 7u);
  for (const MapReflector& reflector : m.reflectors) EXPECT_TRUE(reflector.map_cov_center.has_value());
  EXPECT_FALSE(m.occluders.empty());
  for (const char* file : {"report.txt", "reflectors.csv", "observations.csv", "trajectory.csv",
                           "rejected.csv", "occluders.csv", "comparison.csv", "survey.json"})
    EXPECT_TRUE(std::filesystem::exists(report + "/" + file)) << file;
}

TEST(SurveyDriveCli, CompareFindsAMapEqualToItsTruth) {
  const auto r = testing::run_command(
      fmt::format("{} compare --map {} --truth {}", kSurvey, testing::kDemoMap, testing::kDemoMap));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("matched 24; RMS error 0.00 mm, worst 0.00 mm"), std::string::npos) << r.output;
}

TEST(SurveyDriveCli, BadInputExits2AndABadCommandLine64) {
  const std::string map = testing::temp_path("never.json");
  auto r = testing::run_command(fmt::format("{} drive --log /nonexistent/log --out {}", kSurvey, map));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/nonexistent/log"), std::string::npos) << r.output;

  const std::string anchors = testing::temp_path("anchors.json");
  std::ofstream(anchors) << R"({"anchors": [{"id": 1, "x_m": 1.5, "y_m": 0.1}]})";
  r = testing::run_command(
      fmt::format("{} drive --log {} --out {} --anchors {}", kSurvey, drive_log(), map, anchors));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("/anchors: 2 or more"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(map));

  // An existing map is not replaced without --force.
  std::ofstream(map) << "{}";
  r = testing::run_command(fmt::format("{} drive --log {} --out {}", kSurvey, drive_log(), map));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("give --force"), std::string::npos) << r.output;

  EXPECT_EQ(testing::run_command(kSurvey).exit_code, 64);
  EXPECT_EQ(testing::run_command(kSurvey + " drive --log " + drive_log()).exit_code, 64);  // no --out
  EXPECT_EQ(testing::run_command(kSurvey + " drive --help").exit_code, 0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
