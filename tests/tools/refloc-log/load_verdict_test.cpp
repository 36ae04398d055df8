// The load test's verdict (refloc-log --load-test), on plain reports: each of the four
// checks fails on its own cause and only then, and the report carries the numbers
// deploy/load_test.sh and tests/ops/load_test_check.sh read.

#include "load_verdict.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

ServiceHealth healthy(const std::string& name) {
  ServiceHealth h;
  h.service = name;
  h.heartbeats = 20;
  h.messages_in_logged = 1000;
  h.messages_out_logged = 1000;
  h.last_p99_us = 812.4;
  h.max_p99_us = 1500.6;
  return h;
}

ProcessUsage usage(const std::string& name) {
  ProcessUsage p;
  p.program = name;
  p.cpu_ticks = 500;  // 5 s of CPU at 100 ticks/s
  p.samples = 4;
  p.rss_sum_kb = 4 * 10240;
  p.rss_end_kb = 10240;
  p.rss_peak_kb = 20480;
  return p;
}

struct Measured {
  LoadSamples samples;
  ScanContinuityReport scans;
  LatencyReport latency;
};

/// 20 s at 50 Hz, every scan through, p99 2 ms, two services and the recorder.
Measured passing_run() {
  Measured r;
  r.samples.run.duration_s = 20.0;
  r.samples.run.measured_s = 20.0;
  r.samples.run.cores = 2;
  r.samples.run.max_p99_ms = 5.0;
  r.samples.processes = {usage("pose_solver"), usage("navigator"), usage(kLoadTestRecorder)};
  r.scans.scans = 1000;
  r.scans.expected = 1000;
  r.scans.duration_s = 19.98;
  r.scans.stages = {{"REFLECTORS", 1000, 1000, 0}, {"LASER_POSE", 1000, 1000, 0}};
  r.scans.services = {healthy("navigator"), healthy("pose_solver")};
  r.latency.end_to_end.count = 1000;
  r.latency.end_to_end.p50_ms = 1.0;
  r.latency.end_to_end.p99_ms = 2.0;
  r.latency.end_to_end.max_ms = 3.0;
  return r;
}

LoadChecks judge(const Measured& r) { return judge_load_test(r.samples, r.scans, r.latency); }

/// The table row of `program` in a text report, split at whitespace.
std::vector<std::string> row_of(const std::string& text, const std::string& program) {
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream cells(line);
    std::vector<std::string> row;
    for (std::string cell; cells >> cell;) row.push_back(cell);
    if (!row.empty() && row[0] == program) return row;
  }
  return {};
}

TEST(LoadVerdict, EveryScanThroughFastAndNoRestartPasses) {
  const LoadChecks c = judge(passing_run());
  EXPECT_TRUE(c.no_dropped_scan);
  EXPECT_TRUE(c.latency_p99_within_limit);
  EXPECT_TRUE(c.every_service_reported) << "the recorder sends no HEARTBEAT and is not required to";
  EXPECT_TRUE(c.no_restart);
  EXPECT_TRUE(c.pass());
  EXPECT_DOUBLE_EQ(c.max_p99_ms, 5.0);
}

TEST(LoadVerdict, AScanWithoutLaserPoseFailsOnlyTheDropCheck) {
  Measured r = passing_run();
  r.scans.stages.back().scans_missing = 1;
  const LoadChecks c = judge(r);
  EXPECT_FALSE(c.no_dropped_scan);
  EXPECT_TRUE(c.latency_p99_within_limit && c.every_service_reported && c.no_restart);
  EXPECT_FALSE(c.pass());
}

TEST(LoadVerdict, CountersOnlyTheLoggerMissedAreNotDropped) {
  Measured r = passing_run();
  r.scans.missing = 3;
  r.scans.unlogged_but_processed = 3;
  EXPECT_TRUE(judge(r).no_dropped_scan);
  r.scans.unlogged_but_processed = 2;
  EXPECT_FALSE(judge(r).no_dropped_scan);
}

TEST(LoadVerdict, P99AboveTheLimitFailsAndALimitOfZeroOnlyReports) {
  Measured r = passing_run();
  r.latency.end_to_end.p99_ms = 5.01;
  EXPECT_FALSE(judge(r).latency_p99_within_limit);
  r.latency.end_to_end.p99_ms = 5.0;
  EXPECT_TRUE(judge(r).latency_p99_within_limit) << "the limit itself is within";
  r.latency.end_to_end.p99_ms = 80.0;
  r.samples.run.max_p99_ms = 0.0;
  EXPECT_TRUE(judge(r).latency_p99_within_limit);
  EXPECT_TRUE(judge(r).pass());
}

TEST(LoadVerdict, AServiceWithoutHeartbeatInTheLogFails) {
  Measured r = passing_run();
  r.scans.services.pop_back();  // pose_solver
  const LoadChecks c = judge(r);
  EXPECT_FALSE(c.every_service_reported);
  EXPECT_FALSE(c.pass());
}

TEST(LoadVerdict, APidChangeOrAHeartbeatRestartFails) {
  Measured r = passing_run();
  r.samples.processes[2].pid_restarts = 1;  // even the recorder
  EXPECT_FALSE(judge(r).no_restart);
  r = passing_run();
  r.scans.services[0].restarts = 1;
  EXPECT_FALSE(judge(r).no_restart);
  EXPECT_TRUE(judge(r).every_service_reported);
}

TEST(LoadVerdict, JsonReportCarriesTheNumbersTheScriptsRead) {
  Measured r = passing_run();
  const LoadChecks c = judge(r);
  const auto j = load_test_report_to_json(r.samples, r.scans, r.latency, c);
  EXPECT_EQ(j["scans"]["published"], 1000);
  EXPECT_EQ(j["scans"]["dropped"], 0);
  EXPECT_EQ(j["scans"]["missing_counters"], 0);
  EXPECT_DOUBLE_EQ(j["scans"]["expected_50hz"].get<double>(), 1000.0);
  EXPECT_DOUBLE_EQ(j["scans"]["expected_50hz_over_log"].get<double>(), 1000.0);  // round(50 * 19.98 + 1)
  EXPECT_DOUBLE_EQ(j["latency_ms"]["p99_ms"].get<double>(), 2.0);
  ASSERT_EQ(j["services"].size(), 3u);
  const auto& solver = j["services"][0];
  EXPECT_EQ(solver["service"], "pose_solver");
  EXPECT_DOUBLE_EQ(solver["cpu_percent"].get<double>(), 25.0);  // 5 s of 20 s
  EXPECT_DOUBLE_EQ(solver["rss_mean_mb"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(solver["rss_peak_mb"].get<double>(), 20.0);
  EXPECT_DOUBLE_EQ(solver["heartbeat_p99_us"].get<double>(), 812.4);
  EXPECT_EQ(solver["decode_errors"], 0);
  const auto& recorder = j["services"][2];
  EXPECT_TRUE(recorder["heartbeat_p99_us"].is_null());
  EXPECT_TRUE(recorder["decode_errors"].is_null());
  EXPECT_EQ(j["checks"]["no_dropped_scan"], true);
  EXPECT_DOUBLE_EQ(j["checks"]["max_p99_ms"].get<double>(), 5.0);
  EXPECT_EQ(j["pass"], true);
}

TEST(LoadVerdict, TextReportEndsInTheVerdictAndListsEveryProgram) {
  Measured r = passing_run();
  std::string text = format_load_test_report(r.samples, r.scans, r.latency, judge(r));
  EXPECT_NE(text.find("p99 2  max 3  (1000 scans; p99 limit 5 ms)"), std::string::npos) << text;
  using Row = std::vector<std::string>;
  EXPECT_EQ(row_of(text, "SERVICE"), (Row{"SERVICE", "CPU%", "RSS_MB", "PEAK_MB", "HB_P99_US", "HB_MAXP99",
                                          "IN_LOGGED", "OUT_LOGGED", "DECERR", "RESTARTS"}));
  EXPECT_EQ(row_of(text, "pose_solver"),
            (Row{"pose_solver", "25", "10", "20", "812", "1501", "1000", "1000", "0", "0"}));
  EXPECT_EQ(row_of(text, "lcm-logger"), (Row{"lcm-logger", "25", "10", "20", "-", "-", "-", "-", "-", "0"}));
  EXPECT_EQ(text.substr(text.size() - 5), "PASS\n");
  r.scans.stages.back().scans_missing = 2;
  text = format_load_test_report(r.samples, r.scans, r.latency, judge(r));
  EXPECT_NE(text.find("dropped scans: 2 "), std::string::npos) << text;
  EXPECT_EQ(text.substr(text.size() - 5), "FAIL\n");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
