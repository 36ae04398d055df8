// refloc-log export: a pose2d_t and a laser_scan_t channel to JSON lines and
// CSV, channel selection by regular expression, one CSV file per channel, and
// messages that are not refloc types.

#include "common/json_config.hpp"
#include "lcm_log_fixture.hpp"
#include "log_analysis.hpp"

#include <refloc/laser_scan_t.hpp>
#include <refloc/pose2d_t.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::kT0;

pose2d_t make_pose(int i) {
  pose2d_t p{};
  p.utime = kT0 + i * 40'000;
  p.x = 1.5 + i;
  p.y = -2.25;
  p.theta = 0.125;
  for (int k = 0; k < 9; ++k) p.covariance[k] = k == 0 || k == 4 ? 1e-4 : 0.0;
  p.status = pose2d_t::STATUS_DEGRADED;
  p.reflectors_used = 4;
  p.residual = 0.003;
  return p;
}

laser_scan_t make_scan(int i) {
  laser_scan_t s{};
  s.utime = kT0 + i * 40'000;
  s.scan_counter = 100 + i;
  s.start_angle = -2.35619449f;
  s.angle_increment = 0.0087266462f;
  s.time_increment = 1.0f / 36000.0f;
  s.scan_period = 0.04f;
  s.range_min = 0.05f;
  s.range_max = 20.0f;
  s.ranges = {1.5f, 0.1f, 2.25f};
  s.nranges = 3;
  s.rssi = {200, 0, 65535};
  s.nrssi = 3;
  s.rssi_bits = 16;
  return s;
}

/// Two scans and two poses, plus a message that is not a refloc type.
std::string write_mixed_log() {
  const std::string path = testing::temp_path("mixed.lcmlog");
  testing::LcmLogWriter log(path);
  for (int i = 0; i < 2; ++i) {
    log.write("LMS100_SCAN", kT0 + i * 40'000 + 2'000, make_scan(i));
    log.write("LASER_POSE", kT0 + i * 40'000 + 9'000, make_pose(i));
  }
  log.write_raw("FOREIGN", kT0 + 100'000, {1, 2, 3, 4, 5, 6, 7, 8, 9});
  return path;
}

LogExportResult run_export(const std::string& log, LogExportRequest request) {
  const MessageDecoder decoder;
  const auto summary = analyze_log(log, {}, decoder).summary;
  return export_log(log, summary, request, decoder);
}

TEST(LogExport, JsonLinesKeepEveryFieldWithArraysAsJsonArrays) {
  const std::string out = testing::temp_path("out.jsonl");
  const auto r = run_export(write_mixed_log(), {{"LASER_POSE", "LMS100_SCAN"}, out, ""});
  EXPECT_EQ(r.jsonl.written, 4);
  EXPECT_EQ(r.jsonl.undecoded, 0);
  const auto lines = testing::read_lines(out);
  ASSERT_EQ(lines.size(), 4u);
  const auto scan = nlohmann::json::parse(lines[0]);
  EXPECT_EQ(scan["channel"], "LMS100_SCAN");
  EXPECT_EQ(scan["type"], "laser_scan_t");
  EXPECT_EQ(scan["log_utime"].get<int64_t>(), kT0 + 2'000);
  EXPECT_EQ(scan["msg"]["utime"].get<int64_t>(), kT0);
  EXPECT_EQ(scan["msg"]["scan_counter"].get<int>(), 100);
  EXPECT_EQ(scan["msg"]["ranges"], nlohmann::json::parse("[1.5, 0.1, 2.25]"));  // floats as written
  EXPECT_EQ(scan["msg"]["rssi"], nlohmann::json::parse("[200, 0, 65535]"));
  EXPECT_EQ(scan["msg"]["rssi_bits"].get<int>(), 16);
  EXPECT_DOUBLE_EQ(scan["msg"]["scan_period"].get<double>(), 0.04);
  const auto pose = nlohmann::json::parse(lines[3]);
  EXPECT_EQ(pose["type"], "pose2d_t");
  EXPECT_DOUBLE_EQ(pose["msg"]["x"].get<double>(), 2.5);
  EXPECT_DOUBLE_EQ(pose["msg"]["y"].get<double>(), -2.25);
  EXPECT_EQ(pose["msg"]["covariance"].size(), 9u);
  EXPECT_DOUBLE_EQ(pose["msg"]["covariance"][4].get<double>(), 1e-4);
  EXPECT_EQ(pose["msg"]["status"].get<int>(), 1);
  // Fields keep their declaration order.
  EXPECT_EQ(lines[3].find("\"msg\":{\"utime\":"), lines[3].find("\"msg\":"));
}

TEST(LogExport, CsvOfOneChannelGoesToTheGivenFileWithScalarColumns) {
  const std::string out = testing::temp_path("pose.csv");
  const auto r = run_export(write_mixed_log(), {{"LASER_POSE"}, "", out});
  EXPECT_EQ(r.csv.written, 2);
  ASSERT_EQ(r.csv_files.size(), 1u);
  EXPECT_EQ(r.csv_files.at("LASER_POSE"), out);
  const auto lines = testing::read_lines(out);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0], "log_utime,channel,utime,x,y,theta,covariance,status,reflectors_used,residual");
  EXPECT_EQ(lines[1], std::to_string(kT0 + 9'000) + ",LASER_POSE," + std::to_string(kT0) +
                          ",1.5,-2.25,0.125,0.0001;0.0;0.0;0.0;0.0001;0.0;0.0;0.0;0.0,1,4,0.003");
}

TEST(LogExport, CsvOfLaserScanJoinsArraysWithSemicolons) {
  const std::string out = testing::temp_path("scan.csv");
  run_export(write_mixed_log(), {{"LMS100_SCAN"}, "", out});
  const auto lines = testing::read_lines(out);
  ASSERT_EQ(lines.size(), 3u);
  const auto header = testing::split(lines[0], ',');
  const auto row = testing::split(lines[2], ',');
  ASSERT_EQ(header.size(), row.size());
  auto cell = [&](const std::string& column) {
    for (size_t i = 0; i < header.size(); ++i) {
      if (header[i] == column) return row[i];
    }
    return std::string("<no column>");
  };
  EXPECT_EQ(cell("scan_counter"), "101");
  EXPECT_EQ(cell("nranges"), "3");
  EXPECT_EQ(cell("ranges"), "1.5;0.1;2.25");
  EXPECT_EQ(cell("rssi"), "200;0;65535");
  EXPECT_EQ(cell("angle_increment"), "0.008726646");
  EXPECT_EQ(cell("rssi_bits"), "16");
}

TEST(LogExport, RegexSelectsSeveralChannelsAndCsvSplitsPerChannel) {
  const std::string out = testing::temp_path("all.csv");
  const auto r = run_export(write_mixed_log(), {{"LASER_.*|LMS100_.*"}, "", out});
  EXPECT_EQ(r.channels, (std::vector<std::string>{"LASER_POSE", "LMS100_SCAN"}));
  ASSERT_EQ(r.csv_files.size(), 2u);
  const std::string stem = out.substr(0, out.size() - 4);
  EXPECT_EQ(r.csv_files.at("LASER_POSE"), stem + "_LASER_POSE.csv");
  EXPECT_EQ(r.csv_files.at("LMS100_SCAN"), stem + "_LMS100_SCAN.csv");
  EXPECT_EQ(testing::read_lines(stem + "_LASER_POSE.csv").size(), 3u);
  EXPECT_EQ(testing::read_lines(stem + "_LMS100_SCAN.csv").size(), 3u);
}

TEST(LogExport, ChannelPatternMustMatchTheWholeName) {
  const auto r = run_export(write_mixed_log(), {{"POSE"}, "", ""});
  EXPECT_TRUE(r.channels.empty());  // LASER_POSE is not POSE
}

TEST(LogExport, ForeignMessagesAreMarkedInJsonlAndSkippedInCsv) {
  const std::string jsonl = testing::temp_path("foreign.jsonl");
  const std::string csv = testing::temp_path("foreign.csv");
  const auto r = run_export(write_mixed_log(), {{"FOREIGN"}, jsonl, csv});
  EXPECT_EQ(r.jsonl.undecoded, 1);
  EXPECT_EQ(r.csv.undecoded, 1);
  EXPECT_EQ(r.csv.written, 0);
  const auto line = nlohmann::json::parse(testing::read_lines(jsonl).at(0));
  EXPECT_TRUE(line["type"].is_null());
  EXPECT_EQ(line["bytes"].get<int>(), 9);
}

TEST(LogExport, InvalidRegexIsAConfigError) { EXPECT_THROW(ChannelSelector({"LASER_(("}), ConfigError); }

TEST(LogExport, CsvPathPerChannel) {
  EXPECT_EQ(csv_path_for_channel("out/x.csv", "POSE", true), "out/x.csv");
  EXPECT_EQ(csv_path_for_channel("out/x.csv", "POSE", false), "out/x_POSE.csv");
  EXPECT_EQ(csv_path_for_channel("out.d/x", "A/B", false), "out.d/x_A_B");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
