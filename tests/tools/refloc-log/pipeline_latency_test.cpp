// Scan-to-pose latency from a log: stage delays matched by the scan's utime,
// p50/p99 of the end-to-end latency, scans that never reached LASER_POSE,
// duplicates, and the services' HEARTBEAT processing times.

#include "lcm_log_fixture.hpp"
#include "log_analysis.hpp"
#include "log_report.hpp"

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::kT0;

/// 100 scans at 25 Hz. Scan i: logged 1 ms after its utime; REFLECTORS +2 ms
/// later, REFLECTOR_MATCHES +3 ms, LASER_POSE +(1 + i % 10) ms, so the end-to-end
/// latency is 6..15 ms. Scan 50 never gets a pose; scan 60's pose arrives twice.
std::string write_pipeline_log() {
  const std::string path = testing::temp_path("pipeline.lcmlog");
  testing::LcmLogWriter log(path);
  for (int i = 0; i < 100; ++i) {
    const int64_t scan_utime = kT0 + i * 40'000;
    const int64_t t_scan = scan_utime + 1'000;
    laser_scan_t scan{};
    scan.utime = scan_utime;
    log.write("LMS100_SCAN", t_scan, scan);
    reflector_detections_t det{};
    det.utime = scan_utime;
    log.write("REFLECTORS", t_scan + 2'000, det);
    reflector_matches_t matches{};
    matches.utime = scan_utime;
    log.write("REFLECTOR_MATCHES", t_scan + 5'000, matches);
    if (i == 50) continue;
    pose2d_t pose{};
    pose.utime = scan_utime;
    log.write("LASER_POSE", t_scan + 5'000 + (1 + i % 10) * 1'000, pose);
    if (i == 60) log.write("LASER_POSE", t_scan + 30'000, pose);
  }
  heartbeat_t hb{};
  hb.service = "pose_solver";
  hb.processing_p50_us = 310.0f;
  hb.processing_p99_us = 905.0f;
  hb.messages_in = 99;
  hb.messages_out = 99;
  log.write("HEARTBEAT", kT0 + 4'000'000, hb);
  return path;
}

LatencyReport measure(const std::string& path) {
  const MessageDecoder decoder;
  LogAnalysisOptions options;
  options.latency = true;
  return *analyze_log(path, options, decoder).latency;
}

TEST(PipelineLatency, StageDelaysMatchedByScanUtime) {
  const auto r = measure(write_pipeline_log());
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[0].count, 100u);
  EXPECT_DOUBLE_EQ(r.stages[0].p50_ms, 2.0);
  EXPECT_DOUBLE_EQ(r.stages[0].p99_ms, 2.0);
  EXPECT_DOUBLE_EQ(r.stages[1].p50_ms, 3.0);
  EXPECT_EQ(r.stages[2].count, 99u);
  EXPECT_DOUBLE_EQ(r.stages[2].max_ms, 10.0);
}

TEST(PipelineLatency, EndToEndPercentilesOverScansThatReachedThePose) {
  const auto r = measure(write_pipeline_log());
  // 99 scans with latencies 6..15 ms, ten of each except one 6 ms (scan 50) missing.
  EXPECT_EQ(r.end_to_end.count, 99u);
  EXPECT_DOUBLE_EQ(r.end_to_end.p50_ms, 11.0);
  EXPECT_DOUBLE_EQ(r.end_to_end.p99_ms, 15.0);
  EXPECT_DOUBLE_EQ(r.end_to_end.max_ms, 15.0);  // scan 60's duplicate (30 ms) does not count
  EXPECT_NEAR(r.end_to_end.mean_ms, (10.0 * 105.0 - 6.0) / 99.0, 1e-9);
  EXPECT_EQ(r.reached, (std::vector<size_t>{100, 100, 100, 99}));
}

TEST(PipelineLatency, TheNextChannelEndsEachScanAtItsFirstMessageAfterTheLastStage) {
  PipelineLatency p({"LMS100_SCAN", "REFLECTOR_MATCHES"});
  p.set_next_channel("POSE");
  for (int64_t i = 0; i < 10; ++i) {
    p.add(0, 1000 * i, 1000 * i + 100);
    p.add(1, 1000 * i, 1000 * i + 300);
    p.add_next(1000 * i + 800);  // one POSE per odometry message, 0.5 ms after the matches
  }
  p.add(0, 20'000, 20'100);  // the last scan: matches after the last POSE
  p.add(1, 20'000, 20'300);
  const LatencyReport r = p.report();
  ASSERT_EQ(r.channels.back(), "POSE (next)");
  ASSERT_EQ(r.stages.size(), 2u);
  EXPECT_DOUBLE_EQ(r.stages[1].p50_ms, 0.5);
  EXPECT_EQ(r.end_to_end.count, 10u);
  EXPECT_DOUBLE_EQ(r.end_to_end.p50_ms, 0.7);
  EXPECT_EQ(r.reached, (std::vector<size_t>{11, 11, 10}));
}

TEST(PipelineLatency, HeartbeatProcessingTimesAreReported) {
  const auto r = measure(write_pipeline_log());
  ASSERT_EQ(r.processing.size(), 1u);
  EXPECT_EQ(r.processing[0].service, "pose_solver");
  EXPECT_DOUBLE_EQ(r.processing[0].p50_us, 310.0);
  EXPECT_DOUBLE_EQ(r.processing[0].p99_us, 905.0);
  const std::string text = format_latency_report(r);
  EXPECT_NE(text.find("LMS100_SCAN -> LASER_POSE (total)"), std::string::npos) << text;
  EXPECT_NE(text.find("pose_solver"), std::string::npos) << text;
  const auto j = latency_report_to_json(r);
  EXPECT_DOUBLE_EQ(j["end_to_end"]["p50_ms"].get<double>(), 11.0);
  EXPECT_EQ(j["scans_per_channel"]["LASER_POSE"].get<int>(), 99);
}

TEST(PipelineLatency, WithoutPipelineMessagesNothingIsMeasured) {
  PipelineLatency latency;
  const auto r = latency.report();
  EXPECT_EQ(r.end_to_end.count, 0u);
  EXPECT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(latency.stage_of("LASER_POSE"), 3);
  EXPECT_EQ(latency.stage_of("POSE"), -1);
}

TEST(LatencyStats, PercentilesOfKnownSamples) {
  std::vector<double> us;
  for (int i = 1; i <= 1000; ++i) us.push_back(i * 1000.0);  // 1..1000 ms
  const auto s = latency_stats(us);
  EXPECT_EQ(s.count, 1000u);
  EXPECT_NEAR(s.p50_ms, 500.0, 1.0);
  EXPECT_NEAR(s.p99_ms, 990.0, 1.0);
  EXPECT_DOUBLE_EQ(s.max_ms, 1000.0);
  EXPECT_DOUBLE_EQ(s.mean_ms, 500.5);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
