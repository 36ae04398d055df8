// refloc-status output: the text table's columns and the JSON document.

#include "status_report.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace {

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
  s.counters = {{"resyncs", 0}, {"oversized_clusters", 7}};
  table.update(s, 0.0);
  s.utime += 2'000'000;
  s.messages_in = 50;
  s.messages_out = 48;
  table.update(s, 2.0);
  return table.rows({"reflector_extractor", "pose_solver"}, 2.5);
}

TEST(StatusReport, TableShowsRatesPercentilesErrorsAgeAndMissing) {
  const std::string text = format_status_table(sample_rows());
  EXPECT_NE(text.find("reflector_extractor"), std::string::npos);
  EXPECT_NE(text.find("4242"), std::string::npos);
  EXPECT_NE(text.find("DEGRADED"), std::string::npos);
  EXPECT_NE(text.find(" 25.0 "), std::string::npos);  // 50 in / 2 s
  EXPECT_NE(text.find(" 24.0 "), std::string::npos);  // 48 out / 2 s
  EXPECT_NE(text.find(" 812 "), std::string::npos);
  EXPECT_NE(text.find(" 2210 "), std::string::npos);
  EXPECT_NE(text.find(" 0.5 "), std::string::npos);  // age
  EXPECT_NE(text.find("3 oversized_clusters=7"), std::string::npos);
  EXPECT_EQ(text.find("resyncs"), std::string::npos);  // zero counters are not noise in the table
  EXPECT_NE(text.find("few clusters"), std::string::npos);
  EXPECT_NE(text.find("pose_solver"), std::string::npos);
  EXPECT_NE(text.find("MISSING or stale: pose_solver"), std::string::npos);
}

TEST(StatusReport, JsonHasNumbersAndNullsForUnknown) {
  const auto doc = status_to_json(sample_rows());
  EXPECT_FALSE(doc["ok"].get<bool>());
  EXPECT_EQ(doc["missing"], nlohmann::json::array({"pose_solver"}));
  const auto& e = doc["services"][0];
  EXPECT_EQ(e["service"], "reflector_extractor");
  EXPECT_EQ(e["state"], "DEGRADED");
  EXPECT_DOUBLE_EQ(e["rate_in_hz"].get<double>(), 25.0);
  EXPECT_DOUBLE_EQ(e["rate_out_hz"].get<double>(), 24.0);
  EXPECT_DOUBLE_EQ(e["age_s"].get<double>(), 0.5);
  EXPECT_EQ(e["decode_errors"].get<int>(), 3);
  EXPECT_EQ(e["counters"]["oversized_clusters"].get<int>(), 7);
  EXPECT_EQ(e["counters"]["resyncs"].get<int>(), 0);
  EXPECT_TRUE(e["present"].get<bool>());
  const auto& m = doc["services"][1];
  EXPECT_EQ(m["state"], "MISSING");
  EXPECT_FALSE(m["present"].get<bool>());
}

TEST(StatusReport, AllAliveSummaryLine) {
  HeartbeatTable table;
  HeartbeatSample s;
  s.service = "a";
  table.update(s, 0.0);
  const std::string text = format_status_table(table.rows({"a"}, 0.5));
  EXPECT_NE(text.find("all 1 expected services alive"), std::string::npos);
  EXPECT_NE(text.find(" - "), std::string::npos);  // no rate yet
}

}  // namespace
}  // namespace refloc

namespace refloc {
namespace {

TEST(StatusReport, OneRefreshIsOneJsonLineOrTheTableWithDecodeErrors) {
  const std::vector<ServiceStatus> rows;
  const std::string json = format_status(rows, 3, true, true);
  EXPECT_EQ(json.back(), '\n');
  EXPECT_EQ(json.find('\n'), json.size() - 1) << "one line";
  EXPECT_EQ(nlohmann::json::parse(json)["heartbeat_decode_errors"], 3);
  const std::string text = format_status(rows, 3, false, true);
  EXPECT_EQ(text.rfind("\033[H\033[2J", 0), 0u) << "live mode clears the screen first";
  EXPECT_NE(text.find("3 HEARTBEAT messages could not be decoded"), std::string::npos) << text;
  EXPECT_EQ(format_status(rows, 0, false, false).find("could not be decoded"), std::string::npos);
  EXPECT_EQ(format_status(rows, 0, false, false).rfind("\033", 0), std::string::npos);
}

}  // namespace
}  // namespace refloc
