// refloc-log --scans: dropped scans from the LMS100 scan counter (uint16,
// wrapping), scans that never reached a later stage, and the services'
// HEARTBEAT health (decode errors over restarts, worst handler p99).

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

heartbeat_t beat(const std::string& service, int32_t pid, int64_t decode_errors, float p99_us,
                 int64_t in = 100, int64_t out = 99) {
  heartbeat_t hb{};
  hb.service = service;
  hb.pid = pid;
  hb.messages_in = in;
  hb.messages_out = out;
  hb.decode_errors = decode_errors;
  hb.processing_p50_us = 100.0f;
  hb.processing_p99_us = p99_us;
  hb.ncounters = 1;
  hb.counter_names = {"lost_scans"};
  hb.counter_values = {7};
  return hb;
}

/// 200 scans at 50 Hz, counters from 65500 (wrapping to 0 after 65535). Counters
/// 65500+50..52 (3 scans) and +120 (1 scan) were never logged; scan 80 reached
/// REFLECTORS but no LASER_POSE; the last scan's pose was not logged before the end.
std::string write_scan_log() {
  const std::string path = testing::temp_path("scans.lcmlog");
  testing::LcmLogWriter log(path);
  for (int i = 0; i < 200; ++i) {
    if ((i >= 50 && i <= 52) || i == 120) continue;
    const int64_t scan_utime = kT0 + i * 20'000;
    laser_scan_t scan{};
    scan.utime = scan_utime;
    scan.scan_counter = (65500 + i) & 0xFFFF;
    log.write("LMS100_SCAN", scan_utime + 1'000, scan);
    reflector_detections_t det{};
    det.utime = scan_utime;
    log.write("REFLECTORS", scan_utime + 2'000, det);
    reflector_matches_t matches{};
    matches.utime = scan_utime;
    log.write("REFLECTOR_MATCHES", scan_utime + 3'000, matches);
    if (i == 80 || i == 199) continue;
    pose2d_t pose{};
    pose.utime = scan_utime;
    log.write("LASER_POSE", scan_utime + 4'000, pose);
  }
  log.write("HEARTBEAT", kT0 + 1'000'000, beat("pose_solver", 11, 2, 800.0f, 1000, 900));
  log.write("HEARTBEAT", kT0 + 2'000'000, beat("pose_solver", 11, 3, 2500.0f, 1050, 940));
  log.write("HEARTBEAT", kT0 + 3'000'000, beat("pose_solver", 12, 1, 900.0f, 20, 10));  // restarted
  log.write("HEARTBEAT", kT0 + 3'000'000, beat("reflector_extractor", 20, 0, 300.0f));
  return path;
}

ScanContinuityReport check(const std::string& path) {
  const MessageDecoder decoder;
  LogAnalysisOptions options;
  options.scans = true;
  return *analyze_log(path, options, decoder).scans;
}

TEST(LoadScanContinuity, CounterGapsAcrossTheUint16WrapAreMissingScans) {
  const auto r = check(write_scan_log());
  EXPECT_EQ(r.scans, 196);
  EXPECT_EQ(r.first_counter, 65500);
  EXPECT_EQ(r.last_counter, 65500 + 199);
  EXPECT_EQ(r.expected, 200);
  EXPECT_EQ(r.missing, 4);
  EXPECT_EQ(r.gap_count, 2);
  ASSERT_EQ(r.gaps.size(), 2u);
  EXPECT_EQ(r.gaps[0].after_counter, 65549);
  EXPECT_EQ(r.gaps[0].missing, 3);
  EXPECT_NEAR(r.gaps[0].at_s, 53 * 0.02, 1e-9);
  EXPECT_EQ(r.gaps[1].missing, 1);
  EXPECT_EQ(r.duplicates, 0);
  EXPECT_EQ(r.out_of_order, 0);
  EXPECT_NEAR(r.duration_s, 199 * 0.02, 1e-9);
  EXPECT_NEAR(r.rate_hz, 195 / (199 * 0.02), 1e-9);
}

TEST(LoadScanContinuity, ScansWithoutALaserPoseAreDroppedButNotTheLastOnesBeforeTheLogEnds) {
  const auto r = check(write_scan_log());
  ASSERT_EQ(r.stages.size(), 3u);
  EXPECT_EQ(r.stages[0].channel, "REFLECTORS");
  EXPECT_EQ(r.stages[0].messages, 196);
  EXPECT_EQ(r.stages[0].scans_reached, 196);
  EXPECT_EQ(r.stages[0].scans_missing, 0);
  EXPECT_EQ(r.stages[2].channel, "LASER_POSE");
  EXPECT_EQ(r.stages[2].messages, 194);
  EXPECT_EQ(r.stages[2].scans_reached, 194);
  // Scan 199 (logged 3.981 s in) lies within the 0.5 s tail grace of the log's last event.
  EXPECT_EQ(r.stages[2].scans_missing, 1);  // scan 80 only
  EXPECT_EQ(r.dropped(), 4 + 1);
}

TEST(LoadScanContinuity, AScanTheLoggerMissedButTheExtractorProcessedIsNotDropped) {
  const std::string path = testing::temp_path("unlogged.lcmlog");
  {
    testing::LcmLogWriter log(path);
    for (int i = 0; i < 10; ++i) {
      laser_scan_t scan{};
      scan.utime = kT0 + i * 20'000;
      scan.scan_counter = i;
      if (i != 4 && i != 6) log.write("LMS100_SCAN", scan.utime, scan);  // 4 and 6 lost by the logger...
      reflector_detections_t det{};
      det.utime = scan.utime;
      if (i != 6) log.write("REFLECTORS", scan.utime + 1'000, det);  // ... 6 also by the extractor
      pose2d_t pose{};
      pose.utime = scan.utime;
      if (i != 6) log.write("LASER_POSE", scan.utime + 2'000, pose);
    }
    heartbeat_t hb = beat("pose_solver", 1, 0, 1.0f);
    log.write("HEARTBEAT", kT0 + 2'000'000, hb);  // the log goes on: no tail grace for the scans
  }
  const auto r = check(path);
  EXPECT_EQ(r.missing, 2);
  EXPECT_EQ(r.unlogged_but_processed, 1);
  EXPECT_EQ(r.stages[2].scans_missing, 0);
  EXPECT_EQ(r.dropped(), 1);
}

TEST(LoadScanContinuity, DuplicateAndReorderedCountersAreCountedNotMissing) {
  const std::string path = testing::temp_path("dup.lcmlog");
  {
    testing::LcmLogWriter log(path);
    const int counters[] = {10, 11, 11, 13, 12, 14};
    for (int i = 0; i < 6; ++i) {
      laser_scan_t scan{};
      scan.utime = kT0 + i * 20'000;
      scan.scan_counter = counters[i];
      log.write("LMS100_SCAN", scan.utime, scan);
    }
  }
  const auto r = check(path);
  EXPECT_EQ(r.scans, 6);
  EXPECT_EQ(r.expected, 5);
  EXPECT_EQ(r.missing, 0);
  EXPECT_EQ(r.duplicates, 1);
  EXPECT_EQ(r.out_of_order, 1);
}

TEST(LoadScanContinuity, HeartbeatHealthKeepsTheWorstP99AndDecodeErrorsOverARestart) {
  const auto r = check(write_scan_log());
  ASSERT_EQ(r.services.size(), 2u);
  const ServiceHealth& solver = r.services[0];
  EXPECT_EQ(solver.service, "pose_solver");
  EXPECT_EQ(solver.heartbeats, 3);
  EXPECT_EQ(solver.restarts, 1);
  EXPECT_EQ(solver.decode_errors, 3 + 1);
  EXPECT_DOUBLE_EQ(solver.last_p99_us, 900.0);
  EXPECT_DOUBLE_EQ(solver.max_p99_us, 2500.0);
  EXPECT_EQ(solver.counters.at("lost_scans"), 7);
  EXPECT_EQ(solver.messages_in, 20);
  EXPECT_EQ(solver.messages_in_logged, 50 + 20);
  EXPECT_EQ(solver.messages_out_logged, 40 + 10);
  EXPECT_EQ(r.services[1].service, "reflector_extractor");
  EXPECT_EQ(r.services[1].restarts, 0);
}

TEST(LoadScanContinuity, JsonAndTextNameTheDroppedScansAndEveryService) {
  const auto r = check(write_scan_log());
  const auto j = scan_continuity_to_json(r);
  EXPECT_EQ(j["dropped"], 5);
  EXPECT_EQ(j["missing"], 4);
  EXPECT_EQ(j["stages"][2]["scans_missing"], 1);
  EXPECT_EQ(j["services"][0]["max_processing_p99_us"], 2500.0);
  EXPECT_EQ(j["services"][1]["service"], "reflector_extractor");
  const std::string text = format_scan_continuity(r);
  EXPECT_NE(text.find("dropped scans: 5"), std::string::npos) << text;
  EXPECT_NE(text.find("gap after counter 65549: 3 scans missing"), std::string::npos) << text;
  EXPECT_NE(text.find("reflector_extractor"), std::string::npos) << text;
}

TEST(LoadScanContinuity, OffUnlessAsked) {
  const MessageDecoder decoder;
  EXPECT_FALSE(analyze_log(write_scan_log(), LogAnalysisOptions{}, decoder).scans.has_value());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
