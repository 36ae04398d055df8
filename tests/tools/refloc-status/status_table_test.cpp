// refloc-status's page as a terminal shows it: a fixed set of heartbeats from a whole stack
// (one driver in ERROR, one service missing, long details, many counters) rendered at 100
// columns, and the same with --wide. Also the counter classification behind it.

#include "status_table.hpp"
#include "counter_kind.hpp"
#include "status_report.hpp"

#include <gtest/gtest.h>
#include <refloc/pose2d_t.hpp>

#include <sstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

HeartbeatSample beat(const std::string& service, int32_t pid, int8_t state, const std::string& detail,
                     NamedCounters counters) {
  HeartbeatSample s;
  s.service = service;
  s.pid = pid;
  s.state = state;
  s.state_detail = detail;
  s.processing_p50_us = 310.0;
  s.processing_p99_us = 1250.0;
  s.counters = std::move(counters);
  return s;
}

/// Two heartbeats a second apart from every service but navigator; rates from the counters.
StatusPage stack_page() {
  HeartbeatTable table;
  const std::vector<std::pair<HeartbeatSample, std::pair<int64_t, int64_t>>> stack = {
      {beat("lms100_driver", 4194303, 3,
            "no scan for 12 s: connect to 192.168.0.1:2111 failed: Connection refused; retrying in 2.0 s",
            {{"connects", 3}, {"scans", 25000}, {"reconnects", 2}, {"timeouts", 5}, {"held_scans", 0}}),
       {0, 50}},
      {beat("reflector_extractor", 2001, 1, "",
            {{"scans_compensated_odometry", 24000}, {"rejected_shape", 12}, {"scans_without_reflectors", 3}}),
       {50, 50}},
      {beat("reflector_matcher", 2002, 1, "", {{"global_relocalizations", 1}}), {50, 50}},
      {beat("pose_solver", 2003, 2, "last fix DEGRADED",
            {{"degraded_fixes", 310}, {"range_bias_um", 1200}, {"range_bias_sigma_um", 900}}),
       {50, 50}},
      {beat("mecanum_odometry", 2004, 1, "", {}), {100, 100}},
      {beat("pose_fusion", 2005, 1, "", {{"fixes_accepted", 9000}, {"fixes_rejected_gate", 4}}), {150, 100}},
      {beat("robot_sim", 2006, 1, "", {{"laser_scans_sent", 25000}}), {20, 170}},
      {beat("lcm_logger", 2007, 1, "writing /var/log/refloc/refloc-2026-12-02T17:00:00.lcm, 1.3 GB/h", {}),
       {0, 0}}};
  for (const auto& [sample, rates] : stack) {
    HeartbeatSample s = sample;
    s.decode_errors = s.service == "reflector_matcher" ? 2 : 0;
    table.update(s, 0.0);
    s.utime += 1'000'000;
    s.messages_in += rates.first;
    s.messages_out += rates.second;
    table.update(s, 1.0);
  }
  StatusPage page;
  page.rows = table.rows({"lms100_driver", "reflector_extractor", "reflector_matcher", "pose_solver",
                          "mecanum_odometry", "pose_fusion", "navigator", "robot_sim"},
                         1.2);
  PoseReport pose;
  pose.heard = true;
  pose.last = {0, 12.3456, -3.2109, 0.7854, {}, pose2d_t::STATUS_OK};
  pose.age_s = 0.02;
  pose.sigma_position_m = 0.0031;
  pose.sigma_theta_rad = 0.00087;
  pose.fixes_ok_per_s = 9.5;
  pose.laser_poses_per_s = 10.0;
  page.pose = pose;
  return page;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::string line_starting(const std::string& text, const std::string& start) {
  for (const auto& line : lines_of(text)) {
    if (line.rfind(start, 0) == 0) return line;
  }
  return "";
}

TEST(StatusTable, WholeStackFitsOneHundredColumns) {
  const std::string text = format_status(stack_page(), PageStyle{});
  for (const auto& line : lines_of(text)) EXPECT_LE(line.size(), kStatusColumns) << "'" << line << "'";
  // What HEARTBEAT says, per service: the driver's 50 scans/s out, robot_sim's 170/s.
  EXPECT_NE(line_starting(text, "lms100_driver").find(" 0.0   50.0 "), std::string::npos) << text;
  EXPECT_NE(line_starting(text, "robot_sim").find(" 20.0  170.0 "), std::string::npos) << text;
  EXPECT_NE(line_starting(text, "lms100_driver").find(" ERROR "), std::string::npos) << text;
  EXPECT_NE(line_starting(text, "navigator").find("MISSING"), std::string::npos) << text;
  EXPECT_NE(text.find("MISSING or stale: navigator\n"), std::string::npos) << text;
  EXPECT_NE(text.find("IN ERROR: lms100_driver\n"), std::string::npos) << text;
  std::cout << text;  // the capture the README's example shows
}

TEST(StatusTable, ErrorCountersStandApartFromNormalOnes) {
  const std::string text = format_status(stack_page(), PageStyle{});
  // Each row's ERRORS column counts its non-zero error counters (decode_errors included).
  EXPECT_EQ(line_starting(text, "lms100_driver").substr(69, 6), "     2") << text;
  EXPECT_EQ(line_starting(text, "reflector_matcher").substr(69, 6), "     1") << text;
  EXPECT_EQ(line_starting(text, "mecanum_odometry").substr(69, 6), "     0") << text;
  EXPECT_NE(text.find("  lms100_driver: reconnects=2 timeouts=5\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  reflector_matcher: decode_errors=2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  pose_fusion: fixes_rejected_gate=4\n"), std::string::npos) << text;
  for (const char* normal :
       {" connects=", " scans=", "rejected_shape", "fixes_accepted", "range_bias_um", "laser_scans_sent"})
    EXPECT_EQ(text.find(normal), std::string::npos) << normal << " is normal work, not an error:\n" << text;
}

TEST(StatusTable, CutDetailsFollowInFullAndThePoseLineIsThere) {
  const std::string text = format_status(stack_page(), PageStyle{});
  EXPECT_NE(line_starting(text, "lms100_driver").find("~"), std::string::npos)
      << "detail cut to fit: " << text;
  EXPECT_NE(text.find("details cut above:\n  lms100_driver: no scan for 12 s: connect to 192.168.0.1:2111"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("Connection refused; retrying\n    in 2.0 s\n"), std::string::npos)
      << "wrapped, not lost";
  EXPECT_EQ(line_starting(text, "POSE "),
            "POSE OK x 12.346 y -3.211 m, theta 45.00 deg, sigma 3.1 mm 0.05 deg, fixes 9.5/s OK of 10.0/s")
      << text;
}

TEST(StatusTable, WideShowsEveryColumnOnOneRowEach) {
  PageStyle wide;
  wide.wide = true;
  const std::string text = format_status(stack_page(), wide);
  const std::string driver = line_starting(text, "lms100_driver");
  EXPECT_NE(driver.find("reconnects=2 timeouts=5"), std::string::npos) << driver;
  EXPECT_NE(driver.find("connects=3 scans=25000"), std::string::npos) << "COUNTERS column: " << driver;
  EXPECT_NE(driver.find("Connection refused; retrying in 2.0 s"), std::string::npos) << driver;
  EXPECT_NE(line_starting(text, "SERVICE").find("P50[us]"), std::string::npos);
  EXPECT_GT(driver.size(), kStatusColumns);
  EXPECT_EQ(text.find("details cut above"), std::string::npos);
}

TEST(StatusTable, NarrowColumnsKeepTheirWidthWithHugeNumbers) {
  HeartbeatTable table;
  HeartbeatSample s = beat("a_service_with_a_name_longer_than_the_column", 1, 1, "", {});
  s.processing_p99_us = 123456789.0;
  table.update(s, 0.0);
  s.utime = 1'000'000;
  s.messages_out = 12'345'678;
  table.update(s, 1.0);
  const std::string text = format_status_table(table.rows({}, 1.0));
  for (const auto& line : lines_of(text)) EXPECT_LE(line.size(), kStatusColumns) << line;
  EXPECT_NE(text.find("a_service_with_a_n~"), std::string::npos) << text;
  EXPECT_NE(text.find(">99999"), std::string::npos) << text;
}

TEST(WrapToWidth, BreaksAtSpacesAndIndentsContinuations) {
  EXPECT_EQ(wrap_to_width("aaa bbb ccc\nshort\n", 7), "aaa bbb\n    ccc\nshort\n");
  EXPECT_EQ(wrap_to_width("abcdefghij", 8), "abcdefgh\n    ij");
  for (const auto& line : lines_of(wrap_to_width(std::string(250, 'x') + " y", 100)))
    EXPECT_LE(line.size(), 100u);
}

TEST(CounterKind, NormalWorkIsListedEverythingElseIsAnError) {
  EXPECT_FALSE(is_error_counter("scans"));
  EXPECT_TRUE(is_error_counter("lost_scans"));
  EXPECT_FALSE(is_error_counter("range_bias_um"));
  EXPECT_TRUE(is_error_counter("lcm_recv_buf_clamped_to_bytes"));
  EXPECT_TRUE(is_error_counter("a_counter_added_later"));
  const auto split = split_counters({{"scans", 5}, {"timeouts", 0}, {"reconnects", 1}});
  EXPECT_EQ(split.normal, (NamedCounters{{"scans", 5}}));
  EXPECT_EQ(split.errors, (NamedCounters{{"reconnects", 1}}));
  EXPECT_EQ(error_kinds(4, {{"reconnects", 1}, {"lcm_recv_buf_clamped_to_bytes", 212992}, {"scans", 9}}), 3);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
