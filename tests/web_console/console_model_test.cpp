// ConsoleModel: what the page is sent for each message, decimation, trails.

#include "web_console/console_model.hpp"

#include "common/reflector_map.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

nlohmann::json parsed(const ConsoleFrame& frame) { return nlohmann::json::parse(*frame.text); }

ConsoleModel demo_model(ConsoleModelConfig config = {}) {
  return ConsoleModel(
      config, load_reflector_map(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json"), false);
}

TEST(ConsoleModel, TheMapFrameHoldsEveryReflectorWithItsIdAndIsKeptForLaterClients) {
  ConsoleModel model = demo_model();
  const ConsoleFrame frame = model.map_frame();
  const nlohmann::json j = parsed(frame);
  EXPECT_EQ(frame.latest_key, "map");
  EXPECT_EQ(j["type"], "map");
  ASSERT_EQ(j["reflectors"].size(), model.map().reflectors.size());
  EXPECT_GE(j["reflectors"].size(), 3u);
  EXPECT_EQ(j["reflectors"][0]["id"], model.map().reflectors[0].id);
  EXPECT_DOUBLE_EQ(j["reflectors"][0]["x"].get<double>(), model.map().reflectors[0].map_p_center.x());
  EXPECT_EQ(j["occluders"].size(), model.map().occluders.size());
}

TEST(ConsoleModel, ScansAt50HzReachThePageAt10HzByTheirOwnStamps) {
  ConsoleModel model = demo_model();
  ConsoleScan scan;
  scan.ranges = {1.2345f, 0.0f};
  scan.rssi = {200, 10};
  scan.rssi_bits = 8;
  int sent = 0;
  for (int i = 0; i < 50; ++i) {
    scan.utime = 1'000'000 + i * 20'000 + (i % 2 ? 300 : -300);  // +-0.3 ms jitter
    if (const auto frame = model.on_scan(scan)) {
      ++sent;
      const nlohmann::json j = parsed(*frame);
      EXPECT_EQ(j["ranges_mm"][0], 1235);
      EXPECT_EQ(j["rssi"][0], 200);
    }
  }
  EXPECT_EQ(sent, 10);
  EXPECT_EQ(model.scans_skipped(), 40);
  int detections_sent = 0, matches_sent = 0;
  for (int i = 0; i < 50; ++i) {
    ConsoleDetections detections;
    detections.utime = 1'000'000 + i * 20'000;
    ConsoleMatches matches;
    matches.utime = detections.utime;
    detections_sent += model.on_detections(detections) ? 1 : 0;
    matches_sent += model.on_matches(matches) ? 1 : 0;
  }
  EXPECT_EQ(detections_sent, 10) << "REFLECTORS at the scans' rate";
  EXPECT_EQ(matches_sent, 10) << "REFLECTOR_MATCHES at the scans' rate";
}

TEST(ConsoleModel, ClustersReachThePageForTheSameScansWithTheThresholdAndEachOutcome) {
  ConsoleModel model = demo_model();
  ConsoleScan scan;
  ConsoleClusters clusters;
  clusters.energy_threshold_8bit = 180.0;
  clusters.energy_threshold_raw = 46260.0;
  clusters.clusters = {{10, 14, 5, "accepted", 3.2, 0.1, 240.0}, {40, 52, 13, "too_wide", 2.0, 0.5, 250.0}};
  int both = 0, scans_sent = 0, clusters_sent = 0;
  for (int i = 0; i < 50; ++i) {
    scan.utime = clusters.utime = 1'000'000 + i * 20'000 + (i % 3 ? 200 : -200);
    const auto scan_frame = model.on_scan(scan);
    const auto cluster_frame = model.on_clusters(clusters);
    scans_sent += scan_frame ? 1 : 0;
    clusters_sent += cluster_frame ? 1 : 0;
    both += scan_frame && cluster_frame ? 1 : 0;
    if (!cluster_frame) continue;
    const nlohmann::json j = parsed(*cluster_frame);
    EXPECT_EQ(j["type"], "clusters");
    EXPECT_EQ(j["utime"], clusters.utime);
    EXPECT_EQ(j["energy_threshold_raw"], 46260.0);
    ASSERT_EQ(j["clusters"].size(), 2u);
    EXPECT_EQ(j["clusters"][1]["outcome"], "too_wide");
    EXPECT_EQ(j["clusters"][1]["last_beam"], 52);
  }
  EXPECT_EQ(clusters_sent, 10);
  EXPECT_EQ(both, scans_sent) << "the page draws a scan's clusters only with that scan";
}

TEST(ConsoleModel, TheConsoleIsDegradedWhileNoScanOrNoPoseArrivesAndSaysWhich) {
  ConsoleModel model = demo_model();
  constexpr int64_t kS = 1'000'000;
  EXPECT_TRUE(model.state(10 * kS).ok);  // just started
  EXPECT_TRUE(model.state(13 * kS).ok);  // 3 s: not yet
  const ConsoleState silent = model.state(14 * kS);
  EXPECT_FALSE(silent.ok);
  EXPECT_EQ(silent.detail, "no scan for 4 s; no POSE for 4 s");
  ConsoleScan scan;
  scan.utime = 5 * kS;
  model.on_scan(scan);
  ConsolePose pose;
  pose.utime = 5 * kS;
  pose.status = "OK";
  model.on_pose(PoseSource::kPose, pose);
  EXPECT_TRUE(model.state(15 * kS).ok);
  model.on_scan(scan);  // scans go on, POSE stops (and a LASER_POSE is no POSE)
  model.on_pose(PoseSource::kLaserPose, pose);
  EXPECT_TRUE(model.state(17 * kS).ok);
  model.on_scan(scan);
  const ConsoleState no_pose = model.state(18'500'000);
  EXPECT_FALSE(no_pose.ok);
  EXPECT_EQ(no_pose.detail, "no POSE for 4 s");
}

TEST(ConsoleModel, ScansAreDrawnFromTheLatestOkMatchesHypothesis) {
  ConsoleModel model = demo_model();
  ConsoleMatches matches;
  matches.status = "OK";
  matches.map_T_laser = {1.0, 2.0, 0.5};
  matches.matches.push_back({7, 3.0, 4.0, 1.5, 0.2});
  const nlohmann::json m = parsed(*model.on_matches(matches));
  EXPECT_EQ(m["matches"][0]["map_id"], 7);
  ConsoleScan scan;
  scan.utime = 5;
  const nlohmann::json s = parsed(*model.on_scan(scan));
  EXPECT_DOUBLE_EQ(s["map_T_laser"][1].get<double>(), 2.0);
  matches.status = "LOST";
  matches.map_T_laser = {9.0, 9.0, 0.0};
  matches.utime = 1'000'000;
  EXPECT_TRUE(model.on_matches(matches));
  const nlohmann::json d = parsed(*model.on_detections({}));
  EXPECT_DOUBLE_EQ(d["map_T_laser"][0].get<double>(), 1.0) << "a LOST hypothesis is not drawn on";
}

TEST(ConsoleModel, PosesAreDecimatedButEveryPoseFeedsItsBoundedTrail) {
  ConsoleModelConfig config;
  config.trail_points = 5;
  config.trail_step_m = 0.01;
  config.pose_rate_hz = 10.0;
  ConsoleModel model = demo_model(config);
  int sent = 0;
  for (int i = 0; i < 100; ++i) {  // 100 Hz for 1 s, 2 cm a step
    ConsolePose pose;
    pose.utime = i * 10'000;
    pose.x = 0.02 * i;
    pose.covariance[0] = 1e-6;
    pose.status = "OK";
    if (const auto frame = model.on_pose(PoseSource::kPose, pose)) {
      ++sent;
      EXPECT_EQ(frame->latest_key, "pose/POSE");
      EXPECT_DOUBLE_EQ(parsed(*frame)["covariance"][0].get<double>(), 1e-6);
    }
  }
  EXPECT_EQ(sent, 11) << "the first, then one per 100 ms slot up to 0.99 s (a tenth early counts)";
  EXPECT_EQ(model.trail_size(PoseSource::kPose), 5u);
  EXPECT_EQ(model.trail_size(PoseSource::kGroundTruth), 0u);
  const std::vector<ConsoleFrame> trails = model.trail_frames();
  ASSERT_EQ(trails.size(), 3u);
  EXPECT_FALSE(trails[0].send_now);
  const nlohmann::json t = parsed(trails[0]);
  ASSERT_EQ(t["points"].size(), 5u);
  EXPECT_NEAR(t["points"][0][0].get<double>(), 1.90, 1e-9) << "oldest kept first";
  EXPECT_NEAR(t["points"][4][0].get<double>(), 1.98, 1e-9);
}

TEST(ConsoleModel, ALaserPoseWithoutAPoseStaysOutOfItsTrail) {
  ConsoleModelConfig config;
  config.trail_step_m = 0.01;
  ConsoleModel model = demo_model(config);
  ConsolePose pose;
  pose.x = 5.0;
  pose.y = 3.0;
  pose.status = "OK";
  model.on_pose(PoseSource::kLaserPose, pose);
  for (const char* status : {"LOST", "AMBIGUOUS", "INITIALIZING"}) {
    ConsolePose none;  // the solver's zeros
    none.utime = pose.utime += 20'000;
    none.status = status;
    model.on_pose(PoseSource::kLaserPose, none);
  }
  pose.utime += 20'000;
  pose.x = 5.1;
  pose.status = "DEGRADED";
  model.on_pose(PoseSource::kLaserPose, pose);
  EXPECT_EQ(model.trail_size(PoseSource::kLaserPose), 2u);
}

TEST(ConsoleModel, LocalizationCountsEveryLaserFixPerSecondAndTheOkOnes) {
  ConsoleModel model = demo_model();
  model.localization_frame(0);
  for (int i = 0; i < 100; ++i) {  // 50 Hz for 2 s, every fifth not OK
    ConsolePose fix;
    fix.utime = i * 20'000;
    fix.status = i % 5 == 0 ? "DEGRADED" : "OK";
    model.on_pose(PoseSource::kLaserPose, fix);
  }
  ConsolePose pose;
  pose.status = "OK";
  model.on_pose(PoseSource::kPose, pose);
  const nlohmann::json j = parsed(model.localization_frame(2'000'000));
  EXPECT_DOUBLE_EQ(j["fixes_per_s"].get<double>(), 50.0);
  EXPECT_DOUBLE_EQ(j["ok_fixes_per_s"].get<double>(), 40.0);
  EXPECT_EQ(j["pose_status"], "OK");
  EXPECT_DOUBLE_EQ(parsed(model.localization_frame(3'000'000))["fixes_per_s"].get<double>(), 0.0);
}

TEST(ConsoleModel, TextThatIsNotUtf8IsReplacedNotThrownOn) {
  ConsoleModel model = demo_model();
  ConsoleHeartbeat h;
  h.service = "bad\xff\xfename";
  h.detail = "\xc3";
  ConsoleNavStatus status;
  status.reason = "\x80\x80";
  EXPECT_NO_THROW(parsed(model.on_heartbeat(h)));
  EXPECT_NO_THROW(parsed(model.on_nav_status(status)));
}

TEST(ConsoleModel, EachServicesHeartbeatIsKeptUnderItsOwnName) {
  ConsoleModel model = demo_model();
  ConsoleHeartbeat h;
  h.service = "pose_solver";
  h.state = "DEGRADED";
  h.counters = {{"lost_fixes", 3}};
  const ConsoleFrame frame = model.on_heartbeat(h);
  EXPECT_EQ(frame.latest_key, "heartbeat/pose_solver");
  EXPECT_EQ(parsed(frame)["counters"]["lost_fixes"], 3);
  for (size_t i = 0; i < 2 * ConsoleModel::kMaxKeptServices; ++i) {
    h.service = "invented_" + std::to_string(i);
    const ConsoleFrame invented = model.on_heartbeat(h);
    EXPECT_EQ(invented.latest_key.empty(), i + 1 >= ConsoleModel::kMaxKeptServices) << i;
  }
  h.service = "pose_solver";
  EXPECT_EQ(model.on_heartbeat(h).latest_key, "heartbeat/pose_solver") << "a known service stays kept";
  ConsoleMapHealth health;
  health.reflectors.push_back({4, "missing", 0, 60, 0.0, 0.0});
  EXPECT_EQ(parsed(model.on_map_health(health))["reflectors"][0]["state"], "missing");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
