// The error model's systematic range error (offset, range scale, range walk by RSSI) and
// the 8-bit-in-16-bit RSSI scale: each shown on rendered walls and reflectors.
#include "world_renderer/scan_renderer.hpp"

#include "common/json_config.hpp"
#include "render_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace render_test;

constexpr size_t kReflectorBeam = 270;  // straight ahead: the reflector at 3 m
constexpr size_t kWallBeam = 300;       // +15 deg: the wall at 6 m

World reflector_before_wall() {
  World world = wall_world(6.0);
  add_reflector(world, 1, 3.0, 0.0);
  return world;
}

/// Mean over scans of (rendered range - noise-free range) of one beam [m].
double mean_range_error(const ScanRenderConfig& config, size_t beam, int scans) {
  const World world = reflector_before_wall();
  ScanRenderer truth_renderer(noise_free_config());
  std::mt19937_64 rng(11);
  LaserScan scan;
  truth_renderer.render(world, Pose2{}, 0, rng, scan);
  const double truth = scan.ranges[beam];
  ScanRenderer renderer(config);
  double sum = 0.0;
  for (int k = 0; k < scans; ++k) {
    renderer.render(world, Pose2{}, 0, rng, scan);
    sum += scan.ranges[beam] - truth;
  }
  return sum / scans;
}

ScanRenderConfig walk_config() {
  ScanRenderConfig config;  // default noise: the mean error must equal the bias within it
  config.sensor.range_walk_weak = 0.0;
  config.sensor.range_walk_bright = -0.03;
  config.sensor.range_walk_rssi_weak = 30000.0;
  config.sensor.range_walk_rssi_bright = 60000.0;
  return config;
}

// 400 scans of 12 mm noise: the mean is good to 0.6 mm (1 sigma); 3 mm is five sigma.
constexpr int kScans = 400;
constexpr double kMeanTolerance = 0.003;

TEST(SystematicRangeError, ScaleGrowsWithRangeOnWallsAndReflectors) {
  ScanRenderConfig config;
  config.sensor.range_scale_ppm = 5000.0;  // 5 mm per m
  EXPECT_NEAR(mean_range_error(config, kReflectorBeam, kScans), 0.005 * 2.94, kMeanTolerance);
  EXPECT_NEAR(mean_range_error(config, kWallBeam, kScans), 0.005 * 6.0 / std::cos(15 * kDeg), kMeanTolerance);
  const Lms100ErrorModel m = config.sensor;
  EXPECT_NEAR(systematic_range_error(m, 20.0, 1000.0), 0.1, 1e-12);
}

TEST(SystematicRangeError, WalkShiftsBrightReflectorsButNotWalls) {
  const ScanRenderConfig config = walk_config();
  EXPECT_NEAR(mean_range_error(config, kReflectorBeam, kScans), -0.03, kMeanTolerance);
  EXPECT_NEAR(mean_range_error(config, kWallBeam, kScans), 0.0, kMeanTolerance);
}

TEST(SystematicRangeError, WalkIsLinearBetweenItsTwoRssiLevels) {
  const Lms100ErrorModel m = walk_config().sensor;
  EXPECT_DOUBLE_EQ(range_walk(m, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(range_walk(m, 30000.0), 0.0);
  EXPECT_NEAR(range_walk(m, 45000.0), -0.015, 1e-12);
  EXPECT_DOUBLE_EQ(range_walk(m, 60000.0), -0.03);
  EXPECT_DOUBLE_EQ(range_walk(m, 65535.0), -0.03);
}

TEST(SystematicRangeError, TermsAddUp) {
  ScanRenderConfig config = walk_config();
  config.sensor.range_offset = 0.01;
  config.sensor.range_scale_ppm = 1000.0;
  EXPECT_NEAR(mean_range_error(config, kReflectorBeam, kScans), 0.01 + 0.001 * 2.94 - 0.03, kMeanTolerance);
  EXPECT_NEAR(mean_range_error(config, kWallBeam, kScans), 0.01 + 0.001 * 6.0 / std::cos(15 * kDeg),
              kMeanTolerance);
}

TEST(SystematicRangeError, DefaultsLeaveRangesUnbiased) {
  EXPECT_NEAR(mean_range_error(ScanRenderConfig{}, kReflectorBeam, kScans), 0.0, kMeanTolerance);
  EXPECT_EQ(systematic_range_error(Lms100ErrorModel{}, 15.0, 64000.0), 0.0);
}

TEST(RssiScale, EightBitInSixteenBitChannelNeverExceeds255) {
  World world = reflector_before_wall();
  add_reflector(world, 2, 1.0, 0.8);  // near and bright
  ScanRenderConfig config;
  std::mt19937_64 rng16(4);
  LaserScan scan16;
  render_scan(world, Pose2{}, 0, config, rng16, scan16);
  config.sensor.rssi_scale = RssiScale::k8BitIn16Bit;
  std::mt19937_64 rng8(4);
  LaserScan scan8;
  render_scan(world, Pose2{}, 0, config, rng8, scan8);
  EXPECT_EQ(scan8.rssi_bits, 16);  // the quirk: the 16-bit channel, 8-bit values
  ASSERT_EQ(scan8.rssi.size(), scan16.rssi.size());
  EXPECT_LE(*std::max_element(scan8.rssi.begin(), scan8.rssi.end()), 255);
  EXPECT_GE(scan8.rssi[kReflectorBeam], 230);  // reflectors stay at the top of the 8-bit scale
  for (size_t i = 0; i < scan8.rssi.size(); ++i) {
    EXPECT_EQ(scan8.ranges[i], scan16.ranges[i]) << "beam " << i;  // detection is unchanged
    if (scan16.rssi[i] == 0) {
      EXPECT_EQ(scan8.rssi[i], 0);
    } else {
      EXPECT_NEAR(scan8.rssi[i], scan16.rssi[i] / 257.0, 1.0) << "beam " << i;
    }
  }
}

TEST(SystematicRangeError, ConfigKeysAreReadAndChecked) {
  const JsonConfig file(nlohmann::json::parse(R"({"render": {"sensor": {
      "range_scale_ppm": 250, "range_walk_weak": 0.002, "range_walk_bright": -0.02,
      "range_walk_rssi_weak": 25000, "range_walk_rssi_bright": 62000, "rssi_scale": "8bit_in_16bit"}}})"),
                        "render.json");
  const ScanRenderConfig config = parse_scan_render_config(file, "/render");
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_DOUBLE_EQ(config.sensor.range_scale_ppm, 250.0);
  EXPECT_DOUBLE_EQ(config.sensor.range_walk_weak, 0.002);
  EXPECT_DOUBLE_EQ(config.sensor.range_walk_bright, -0.02);
  EXPECT_DOUBLE_EQ(config.sensor.range_walk_rssi_weak, 25000.0);
  EXPECT_DOUBLE_EQ(config.sensor.range_walk_rssi_bright, 62000.0);
  EXPECT_EQ(config.sensor.rssi_scale, RssiScale::k8BitIn16Bit);

  const auto message_of = [](const char* sensor) {
    const JsonConfig bad(nlohmann::json::parse(std::string(R"({"sensor": )") + sensor + "}"), "bad.json");
    try {
      parse_lms100_error_model(bad, "/sensor");
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message_of(R"({"rssi_scale": "12bit"})").find("/sensor/rssi_scale"), std::string::npos);
  EXPECT_NE(message_of(R"({"range_walk_rssi_weak": 50000, "range_walk_rssi_bright": 40000})")
                .find("/sensor/range_walk_rssi_bright"),
            std::string::npos);
  EXPECT_NE(message_of(R"({"range_scale_ppm": 1e6})").find("bad.json"), std::string::npos);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
