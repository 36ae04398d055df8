// refloc-status output: the JSON document and one refresh as printed (the table's layout is
// status_table_test's).

#include "status_report.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<ServiceStatus> sample_rows() {
  HeartbeatTable table;
  HeartbeatSample s;
  s.service = "reflector_extractor";
  s.pid = 4242;
  s.state = 2;  // DEGRADED
  s.state_detail = "few clusters";
  s.utime = 1'000'000;
  s.decode_errors = 3;
  s.processing_p50_us = 812.4;
  s.processing_p99_us = 2210.0;
  s.counters = {{"resyncs", 0}, {"oversized_clusters", 7}, {"scans_compensated_odometry", 40}};
  table.update(s, 0.0);
  s.utime += 2'000'000;
  s.messages_in = 50;
  s.messages_out = 48;
  table.update(s, 2.0);
  return table.rows({"reflector_extractor", "pose_solver"}, 2.5);
}

TEST(StatusReport, JsonHasNumbersNullsForUnknownAndErrorCountersApart) {
  const auto doc = status_to_json(sample_rows());
  EXPECT_FALSE(doc["ok"].get<bool>());
  EXPECT_EQ(doc["missing"], nlohmann::json::array({"pose_solver"}));
  EXPECT_EQ(doc["in_error"], nlohmann::json::array());
  const auto& e = doc["services"][0];
  EXPECT_EQ(e["service"], "reflector_extractor");
  EXPECT_EQ(e["state"], "DEGRADED");
  EXPECT_DOUBLE_EQ(e["rate_in_hz"].get<double>(), 25.0);
  EXPECT_DOUBLE_EQ(e["rate_out_hz"].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(e["age_s"].get<double>(), 0.5);
  EXPECT_EQ(e["decode_errors"].get<int>(), 3);
  EXPECT_EQ(e["counters"]["oversized_clusters"].get<int>(), 7);
  EXPECT_EQ(e["counters"]["resyncs"].get<int>(), 0);
  EXPECT_EQ(e["error_counters"], nlohmann::json({{"oversized_clusters", 7}}));
  EXPECT_TRUE(e["present"].get<bool>());
  const auto& m = doc["services"][1];
  EXPECT_EQ(m["state"], "MISSING");
  EXPECT_FALSE(m["present"].get<bool>());
}

TEST(StatusReport, OneRefreshIsOneJsonLineOrTheTableWithDecodeErrors) {
  StatusPage page;
  page.heartbeat_decode_errors = 3;
  PageStyle style;
  style.json = true;
  const std::string json = format_status(page, style);
  EXPECT_EQ(json.back(), '\n');
  EXPECT_EQ(json.find('\n'), json.size() - 1) << "one line";
  EXPECT_EQ(nlohmann::json::parse(json)["heartbeat_decode_errors"], 3);
  EXPECT_FALSE(nlohmann::json::parse(json).contains("pose")) << "no pose watched, none reported";
  style.json = false;
  style.clear_screen = true;
  const std::string text = format_status(page, style);
  EXPECT_EQ(text.rfind("\033[H\033[2J", 0), 0u) << "live mode clears the screen first";
  EXPECT_NE(text.find("3 HEARTBEAT messages could not be decoded"), std::string::npos) << text;
  page.heartbeat_decode_errors = 0;
  style.clear_screen = false;
  EXPECT_EQ(format_status(page, style).find("could not be decoded"), std::string::npos);
  EXPECT_EQ(format_status(page, style).rfind("\033", 0), std::string::npos);
}

TEST(StatusReport, JsonCarriesThePose) {
  StatusPage page;
  PoseReport pose;
  pose.heard = true;
  pose.last.x_m = 1.5;
  pose.last.status = 0;
  pose.sigma_position_m = 0.003;
  pose.fixes_ok_per_s = 9.5;
  page.pose = pose;
  PageStyle style;
  style.json = true;
  const auto doc = nlohmann::json::parse(format_status(page, style));
  EXPECT_EQ(doc["pose"]["status"], "OK");
  EXPECT_DOUBLE_EQ(doc["pose"]["x_m"].get<double>(), 1.5);
  EXPECT_DOUBLE_EQ(doc["pose"]["sigma_position_m"].get<double>(), 0.003);
  EXPECT_TRUE(doc["pose"]["sigma_theta_rad"].is_null()) << "unusable sigma is null";
  EXPECT_DOUBLE_EQ(doc["pose"]["fixes_ok_per_s"].get<double>(), 9.5);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
