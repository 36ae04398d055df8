#include "reflector_extractor/rssi_scale.hpp"
#include "reflector_extractor/extractor_node.hpp"

#include "scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kScanPeriod_us = 20'000;  // 50 Hz

/// What a sensor sending 8-bit values in its 16-bit channel sends for the same scene.
LaserScan as_8bit_in_16bit(LaserScan scan) {
  for (int32_t& v : scan.rssi) v = static_cast<int32_t>(std::lround(static_cast<double>(v) / 257.0));
  return scan;
}

/// Scenes of the extractor's tests: reflectors at 1-5 m with dull walls, bright tape.
std::vector<SyntheticScene> scenes() {
  std::vector<SyntheticScene> out;
  for (double range : {1.0, 2.0, 3.5, 5.0}) {
    SyntheticScene s;
    s.cylinders = {test::cylinder_at(range, 0.3), test::cylinder_at(range + 0.5, -0.8)};
    s.segments = {test::dull_wall_behind(range, 0.3), test::dull_wall_behind(range + 0.5, -0.8),
                  test::flat_strip(2.0, 1.5, 0.3, 230.0)};
    out.push_back(s);
  }
  return out;
}

LaserScan scan_at(const SyntheticScene& scene, int k, uint32_t seed) {
  std::mt19937 rng(seed);
  SyntheticScanConfig config;
  config.utime = 1'000'000 + k * kScanPeriod_us;
  LaserScan scan = render_synthetic_scan(scene, config, rng);
  scan.scan_counter = static_cast<uint32_t>(k);
  return scan;
}

TEST(RssiScaleStream, EightBitValuesInTheSixteenBitChannelGiveTheNativeDetections) {
  ExtractorServiceConfig config;
  config.motion_compensation = false;
  ExtractorNode native(config, Pose2{});     // the scene's 16-bit RSSI
  ExtractorNode declared(config, Pose2{});   // the same rounded 8-bit values, rssi_bits 8
  ExtractorNode eight_bit(config, Pose2{});  // those values in the 16-bit channel
  const std::vector<SyntheticScene> all = scenes();
  int native_count = 0, declared_count = 0, eight_bit_count = 0, native_after_verdict = 0, scale_events = 0;
  int k = 0;
  for (int round = 0; round < 25; ++round) {
    for (const SyntheticScene& scene : all) {
      const LaserScan scan = scan_at(scene, k, static_cast<uint32_t>(100 + k));
      const std::vector<ReflectorDetection> expected = native.on_scan(scan).detections;
      LaserScan declared_scan = as_8bit_in_16bit(scan);
      declared_scan.rssi_bits = 8;
      const std::vector<ReflectorDetection> same_values = declared.on_scan(declared_scan).detections;
      const ExtractorOutput& b = eight_bit.on_scan(as_8bit_in_16bit(scan));
      for (const NodeEvent& e : b.events)
        scale_events += e.counter != nullptr && std::string(e.counter) == "rssi_scale_changes";
      native_count += static_cast<int>(expected.size());
      declared_count += static_cast<int>(same_values.size());
      eight_bit_count += static_cast<int>(b.detections.size());
      if (k >= RssiScaleConfig{}.min_scans - 1) {
        native_after_verdict += static_cast<int>(expected.size());
        ASSERT_EQ(b.detections.size(), expected.size()) << "scan " << k;
        ASSERT_EQ(b.detections.size(), same_values.size()) << "scan " << k;
        for (size_t i = 0; i < expected.size(); ++i) {
          EXPECT_EQ(b.detections[i].laser_p_center, same_values[i].laser_p_center);
          // Rounding to 8 bits may keep or drop a partial edge beam (edge_rssi_ratio).
          EXPECT_NEAR((b.detections[i].laser_p_center - expected[i].laser_p_center).norm(), 0.0, 5e-3);
        }
      } else {
        EXPECT_TRUE(b.detections.empty()) << "before the verdict nothing reaches the threshold";
      }
      ++k;
    }
  }
  std::printf(
      "detections over %d scans: native 16-bit %d, 8-bit declared %d, 8-bit in 16-bit %d (native from the "
      "verdict on: %d)\n",
      k, native_count, declared_count, eight_bit_count, native_after_verdict);
  EXPECT_EQ(scale_events, 1);
  EXPECT_EQ(eight_bit.rssi_scale(), RssiScale::k8bitIn16bit);
  EXPECT_EQ(native.rssi_scale(), RssiScale::kNative);
  EXPECT_EQ(eight_bit_count, native_after_verdict);
  EXPECT_GT(native_count, 150);
  const ExtractorHealth h = eight_bit.health(1, 1'000'000 + k * kScanPeriod_us, "LMS100_SCAN");
  EXPECT_EQ(h.state, ExtractorHealth::State::kOk);
  EXPECT_NE(h.detail.find("RSSI 8-bit in the 16-bit channel"), std::string::npos) << h.detail;
  EXPECT_EQ(h.rssi_scale_8bit, 1);
  EXPECT_EQ(native.health(1, 1'000'000 + k * kScanPeriod_us, "LMS100_SCAN").rssi_scale_8bit, -1);
}

TEST(RssiScaleDetector, AValueAbove255SwitchesBackAndTheEvidenceStartsOver) {
  RssiScaleDetector detector;
  const LaserScan bright = scan_at(scenes()[0], 0, 7);
  const LaserScan dim = as_8bit_in_16bit(bright);
  std::vector<NodeEvent> events;
  detector.observe(dim, events);
  EXPECT_EQ(detector.scale(), RssiScale::kNative) << "one scan is not yet a verdict";
  detector.observe(dim, events);
  ASSERT_EQ(detector.scale(), RssiScale::k8bitIn16bit);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_NE(events[0].log.find("8-bit scale"), std::string::npos) << events[0].log;
  detector.observe(bright, events);
  EXPECT_EQ(detector.scale(), RssiScale::kNative);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_STREQ(events[1].counter, "rssi_scale_changes");
  EXPECT_NE(events[1].log.find("back on the 16-bit scale"), std::string::npos) << events[1].log;
  detector.observe(dim, events);
  EXPECT_EQ(detector.scale(), RssiScale::kNative) << "the evidence started over";
  detector.observe(dim, events);
  EXPECT_EQ(detector.scale(), RssiScale::k8bitIn16bit);
}

TEST(RssiScaleDetector, NeedsEnoughEchoesAndLeavesEightBitSensorsAndFixedModesAlone) {
  LaserScan few = as_8bit_in_16bit(scan_at(scenes()[0], 0, 8));
  for (size_t i = 50; i < few.ranges.size(); ++i) few.ranges[i] = 0.0f;  // 50 echoes a scan at most
  std::vector<NodeEvent> events;
  RssiScaleDetector detector;
  for (int i = 0; i < 5; ++i) detector.observe(few, events);
  EXPECT_EQ(detector.scale(), RssiScale::kNative) << "250 echoes < 300";

  LaserScan eight = as_8bit_in_16bit(scan_at(scenes()[0], 0, 9));
  eight.rssi_bits = 8;
  RssiScaleDetector on_8bit;
  for (int i = 0; i < 20; ++i) on_8bit.observe(eight, events);
  EXPECT_EQ(on_8bit.scale(), RssiScale::kNative);  // rssi_bits 8 is read as 8-bit anyway

  RssiScaleConfig native_only;
  native_only.mode = RssiScaleConfig::Mode::kNative;
  RssiScaleDetector fixed(native_only);
  eight.rssi_bits = 16;
  for (int i = 0; i < 20; ++i) fixed.observe(eight, events);
  EXPECT_EQ(fixed.scale(), RssiScale::kNative);
  EXPECT_TRUE(events.empty());

  RssiScaleConfig forced;
  forced.mode = RssiScaleConfig::Mode::k8bitIn16bit;
  EXPECT_EQ(RssiScaleDetector(forced).scale(), RssiScale::k8bitIn16bit);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
