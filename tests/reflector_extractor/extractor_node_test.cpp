#include "reflector_extractor/extractor_node.hpp"

#include "scenes.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace refloc {
namespace {

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
  EXPECT_EQ(out.compensation, CompensationOutcome::kCompensated);
  EXPECT_EQ(out.detections[0].laser_p_center, expected[0].laser_p_center);
  EXPECT_EQ(out.utime, scan.utime);
  EXPECT_EQ(counters_of(out).count("scans_without_fresh_odometry"), 0u);
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

TEST(ExtractorHealth, StartingAndWaitingForTheScanChannelUntilAnyMessageThenOk) {
  ExtractorNode node(ExtractorServiceConfig{}, Pose2{});
  const ExtractorHealth waiting = node.health(0, 5'000'000, "LMS100_SCAN");
  EXPECT_EQ(waiting.state, ExtractorHealth::State::kStarting);
  EXPECT_EQ(waiting.detail, "waiting for LMS100_SCAN");
  const ExtractorHealth ok = node.health(1, 5'000'000, "LMS100_SCAN");
  EXPECT_EQ(ok.state, ExtractorHealth::State::kOk);
  EXPECT_EQ(ok.detail, "");
}

}  // namespace
}  // namespace refloc
