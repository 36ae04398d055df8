#include "reflector_extractor/extractor_node.hpp"

#include "reflector_extractor/motion_compensation.hpp"
#include "scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

LaserScan scan_with_one_reflector(uint32_t seed) {
  SyntheticScene scene;
  scene.cylinders = {test::cylinder_at(2.0, 0.3)};
  scene.segments = {test::dull_wall_behind(2.0, 0.3)};
  std::mt19937 rng(seed);
  return render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
}

std::map<std::string, int64_t> counters_of(const ExtractorOutput& out) {
  std::map<std::string, int64_t> c;
  out.for_each_counter([&](const char* name, int64_t by) { c[name] += by; });
  return c;
}

TEST(ExtractorNode, DetectionsAreTheExtractorsCompensatedWithFreshOdometry) {
  ExtractorServiceConfig config;
  const Pose2 mount{0.2, 0.0, 0.0};
  ExtractorNode node(config, mount);
  const LaserScan scan = scan_with_one_reflector(1);
  node.on_odometry({scan.utime - 5'000, {1.0, 0.0, 0.5}, Pose2{}, 0.0});
  const ExtractorOutput& out = node.on_scan(scan);

  ReflectorExtractor extractor(config.extractor);
  std::vector<ReflectorDetection> expected = extractor.extract(scan);
  MotionCompensator compensator(true, config.odometry_max_age, mount);
  compensator.on_odometry({scan.utime - 5'000, {1.0, 0.0, 0.5}, Pose2{}, 0.0});
  compensator.apply(expected, scan.utime);
  ASSERT_EQ(out.detections.size(), 1u);
  EXPECT_EQ(out.compensation, CompensationOutcome::kOdometry);
  EXPECT_EQ(out.detections[0].laser_p_center, expected[0].laser_p_center);
  EXPECT_EQ(out.utime, scan.utime);
  EXPECT_EQ(counters_of(out).count("scans_without_fresh_odometry"), 0u);
}

TEST(ExtractorNode, ClustersAndTheThresholdOnTheScansOwnRssiScaleComeWithEveryScan) {
  ExtractorServiceConfig config;
  config.motion_compensation = false;
  ExtractorNode node(config, Pose2{});
  LaserScan scan = scan_with_one_reflector(4);
  const ExtractorOutput& native = node.on_scan(scan);
  ASSERT_EQ(native.clusters.size(), 1u);
  EXPECT_EQ(native.clusters[0].outcome, ClusterOutcome::kAccepted);
  EXPECT_EQ(native.clusters[0].first_beam, native.detections[0].first_beam);
  EXPECT_EQ(native.energy_threshold_8bit, 180.0);
  EXPECT_EQ(native.energy_threshold_raw, 180.0 * 257.0);  // the 16-bit channel
  EXPECT_FALSE(native.rssi_read_as_8bit);
  // A sensor that sends 8-bit values in the 16-bit channel: once detected, the threshold is 180
  // on that channel, where a plot of its raw values must draw it.
  for (int i = 0; i < 3; ++i) {
    scan = scan_with_one_reflector(5 + static_cast<uint32_t>(i));
    scan.utime += (i + 1) * 20'000;
    scan.scan_counter += static_cast<uint32_t>(i + 1);
    for (int32_t& v : scan.rssi) v /= 257;
    node.on_scan(scan);
  }
  const ExtractorOutput& read_as_8bit = node.on_scan(scan);
  ASSERT_EQ(node.rssi_scale(), RssiScale::k8bitIn16bit);
  EXPECT_TRUE(read_as_8bit.rssi_read_as_8bit);
  EXPECT_EQ(read_as_8bit.energy_threshold_raw, 180.0);
}

TEST(ExtractorNode, AScanWithoutFreshOdometryBumpsScansWithoutFreshOdometry) {
  ExtractorNode node(ExtractorServiceConfig{}, Pose2{});
  const LaserScan scan = scan_with_one_reflector(2);
  node.on_odometry({scan.utime - 300'000, {1.0, 0.0, 0.0}, Pose2{}, 0.0});  // 0.3 s old, max age 0.2 s
  const auto counters = counters_of(node.on_scan(scan));
  EXPECT_EQ(counters.at("scans_without_fresh_odometry"), 1);
  EXPECT_EQ(counters.count("scans_without_reflectors"), 0u);
}

TEST(ExtractorNode, AScanWithoutReflectorsBumpsItsCounterAndTheRejectionCountersAlwaysAppear) {
  ExtractorServiceConfig config;
  config.motion_compensation = false;
  ExtractorNode node(config, Pose2{});
  SyntheticScene dull;
  dull.segments = {test::dull_wall_behind(2.0, 0.0)};
  std::mt19937 rng(3);
  const auto counters = counters_of(node.on_scan(render_synthetic_scan(dull, SyntheticScanConfig{}, rng)));
  EXPECT_EQ(counters.at("scans_without_reflectors"), 1);
  EXPECT_EQ(counters.at("rejected_too_few_beams"), 0);
  EXPECT_EQ(counters.at("rejected_shape"), 0);
  EXPECT_EQ(counters.at("rejected_occluded"), 0);
  EXPECT_EQ(counters.count("scans_without_fresh_odometry"), 0u);  // compensation is off
}

/// n OK fixes 20 ms apart ending 20 ms before scan_utime, of a robot holding twist.
void feed_fixes(ExtractorNode& node, int64_t scan_utime, const BodyTwist& twist, int n) {
  for (int k = 0; k < n; ++k) {
    const double t = -0.02 * (n - k);
    node.on_laser_pose({scan_utime + static_cast<int64_t>(std::llround(t * 1e6)),
                        Pose2{2.0, 1.0, 0.5} * se2_exp(twist, t), Eigen::Matrix3d::Identity() * 1e-5, true});
  }
}

bool has_event(const ExtractorOutput& out, const std::string& counter, const std::string& text) {
  for (const NodeEvent& e : out.events) {
    const bool counter_matches = counter.empty() ? e.counter == nullptr : e.counter && counter == e.counter;
    if (counter_matches && e.log.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(ExtractorNode, OdometryFirstFixesSecondNoneThirdWithTheirCounters) {
  const Pose2 mount{0.3, 0.0, 0.0};
  const BodyTwist twist{0.8, 0.0, 0.4};
  LaserScan scan = scan_with_one_reflector(4);
  const std::vector<ReflectorDetection> measured = ReflectorExtractor(ExtractorConfig{}).extract(scan);
  ASSERT_EQ(measured.size(), 1u);

  // Fresh odometry and fixes: odometry wins.
  ExtractorNode both(ExtractorServiceConfig{}, mount);
  feed_fixes(both, scan.utime, {0.5, 0.0, 0.0}, 15);
  both.on_odometry({scan.utime - 5'000, twist, Pose2{}, 0.0});
  const ExtractorOutput& by_odometry = both.on_scan(scan);
  std::vector<ReflectorDetection> expected = measured;
  compensate_motion(expected, scan.utime, twist, mount);
  EXPECT_EQ(by_odometry.compensation, CompensationOutcome::kOdometry);
  EXPECT_EQ(by_odometry.detections[0].laser_p_center, expected[0].laser_p_center);
  auto counters = counters_of(by_odometry);
  EXPECT_EQ(counters.at("scans_compensated_odometry"), 1);
  EXPECT_EQ(counters.count("scans_compensated_fixes"), 0u);
  EXPECT_EQ(counters.count("scans_without_fresh_odometry"), 0u);
  EXPECT_TRUE(has_event(by_odometry, "", "motion compensation from ODOMETRY"));

  // Odometry 0.3 s old (max age 0.2 s), fixes of the same twist: the fixes' twist.
  ExtractorNode stale(ExtractorServiceConfig{}, mount);
  stale.on_odometry({scan.utime - 300'000, {0.1, 0.0, 0.0}, Pose2{}, 0.0});
  feed_fixes(stale, scan.utime, twist, 15);
  const ExtractorOutput& by_fixes = stale.on_scan(scan);
  EXPECT_EQ(by_fixes.compensation, CompensationOutcome::kFixes);
  // The fitted twist is the arc's chord speed (sin(x)/x of 0.8 m/s), so the centre agrees
  // with the odometry-compensated one to far less than a millimetre.
  EXPECT_LT((by_fixes.detections[0].laser_p_center - expected[0].laser_p_center).norm(), 1e-5);
  EXPECT_GT((measured[0].laser_p_center - expected[0].laser_p_center).norm(), 1e-3);  // it did move
  counters = counters_of(by_fixes);
  EXPECT_EQ(counters.at("scans_compensated_fixes"), 1);
  EXPECT_EQ(counters.at("scans_without_fresh_odometry"), 1);
  EXPECT_EQ(counters.count("scans_compensated_odometry"), 0u);
  EXPECT_EQ(counters.count("scans_without_motion_source"), 0u);
  EXPECT_TRUE(has_event(by_fixes, "", "motion compensation from LASER_POSE fixes (ODOMETRY 0.30 s"));

  // Neither: as measured.
  ExtractorNode none(ExtractorServiceConfig{}, mount);
  feed_fixes(none, scan.utime, twist, 4);  // fewer than min_fixes 5
  const ExtractorOutput& as_measured = none.on_scan(scan);
  EXPECT_EQ(as_measured.compensation, CompensationOutcome::kNoMotionSource);
  EXPECT_EQ(as_measured.detections[0].laser_p_center, measured[0].laser_p_center);
  counters = counters_of(as_measured);
  EXPECT_EQ(counters.at("scans_without_motion_source"), 1);
  EXPECT_EQ(counters.at("scans_without_fresh_odometry"), 1);
  EXPECT_TRUE(has_event(as_measured, "", "no motion compensation: no ODOMETRY, fixes: too few fixes (4"));
}

TEST(ExtractorNode, AChangeOfMotionSourceIsCountedAndLoggedOnlyWhenItChanges) {
  ExtractorNode node(ExtractorServiceConfig{}, Pose2{});
  LaserScan scan = scan_with_one_reflector(5);
  const BodyTwist twist{0.8, 0.0, 0.0};
  std::vector<std::string> sources;
  int changes = 0;
  for (int k = 0; k < 40; ++k) {
    scan.utime = 1'700'000'000'000'000 + k * 20'000;
    scan.scan_counter = static_cast<uint32_t>(k);
    if (k < 10) node.on_odometry({scan.utime - 2'000, twist, Pose2{}, 0.0});  // odometry stops at k = 10
    node.on_laser_pose({scan.utime - 20'000, Pose2{0.8 * 0.02 * (k - 1), 0.0, 0.0},
                        Eigen::Matrix3d::Identity() * 1e-5, true});
    const ExtractorOutput& out = node.on_scan(scan);
    if (sources.empty() || sources.back() != to_string(out.compensation))
      sources.push_back(to_string(out.compensation));
    for (const NodeEvent& e : out.events)
      changes += e.counter && std::string(e.counter) == "motion_source_changes";
  }
  // Odometry until 0.2 s after its last sample (k = 9 + 10), then the fixes.
  EXPECT_EQ(sources, (std::vector<std::string>{"odometry", "fixes"}));
  EXPECT_EQ(changes, 1);
}

TEST(ExtractorNode, LaserPoseFixesAreJudgedAndOnlyOkOnesUsed) {
  ExtractorNode node(ExtractorServiceConfig{}, Pose2{});
  const LaserScan scan = scan_with_one_reflector(6);
  feed_fixes(node, scan.utime - 20'000, {0.8, 0.0, 0.0}, 4);  // 4 good ones, ending 40 ms before
  const int64_t t = scan.utime - 20'000;
  const Eigen::Matrix3d cov = Eigen::Matrix3d::Identity() * 1e-5;
  const auto rejected_by = [&](const LaserPoseFix& fix) {
    const std::vector<NodeEvent>& events = node.on_laser_pose(fix, t);
    return events.size() == 1 && events[0].counter ? std::string(events[0].counter) : std::string("none");
  };
  EXPECT_EQ(rejected_by({t, {NAN, 1.0, 0.5}, cov, true}), "rejected_laser_pose_nonfinite");
  EXPECT_EQ(rejected_by({t, {2.0, 1.0, INFINITY}, cov, true}), "rejected_laser_pose_nonfinite");
  EXPECT_EQ(rejected_by({t, {2e4, 1.0, 0.5}, cov, true}), "rejected_laser_pose_out_of_bounds");
  EXPECT_EQ(rejected_by({t, {2.0, 1.0, 0.5}, Eigen::Matrix3d::Identity() * -1.0, true}),
            "rejected_laser_pose_covariance");
  EXPECT_EQ(rejected_by({t + 3'600'000'000, {2.0, 1.0, 0.5}, cov, true}), "rejected_laser_pose_stamp_ahead");
  EXPECT_TRUE(node.on_laser_pose({t, {NAN, NAN, NAN}, cov * 1e11, false}, t).empty());  // LOST: not used
  // Only the 4 good fixes are in: too few, nothing compensates.
  EXPECT_EQ(node.on_scan(scan).compensation, CompensationOutcome::kNoMotionSource);
}

TEST(ExtractorNode, FixVelocityDisabledLeavesScansWithoutOdometryAsMeasured) {
  ExtractorServiceConfig config;
  config.fix_velocity.enabled = false;
  ExtractorNode node(config, Pose2{});
  const LaserScan scan = scan_with_one_reflector(7);
  feed_fixes(node, scan.utime, {0.8, 0.0, 0.0}, 15);
  const ExtractorOutput& out = node.on_scan(scan);
  EXPECT_EQ(out.compensation, CompensationOutcome::kNoMotionSource);
  EXPECT_TRUE(has_event(out, "", "fixes not used (fix_velocity/enabled false)"));
}

TEST(ExtractorHealth, StartingAndWaitingForTheScanChannelUntilAnyMessageThenOk) {
  ExtractorNode node(ExtractorServiceConfig{}, Pose2{});
  const ExtractorHealth waiting = node.health(0, 5'000'000, "LMS100_SCAN");
  EXPECT_EQ(waiting.state, ExtractorHealth::State::kStarting);
  EXPECT_EQ(waiting.detail, "waiting for LMS100_SCAN");
  const ExtractorHealth ok = node.health(1, 5'000'000, "LMS100_SCAN");
  EXPECT_EQ(ok.state, ExtractorHealth::State::kOk);
  EXPECT_EQ(ok.detail, "");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
