#include "world_renderer/scan_renderer.hpp"

#include "common/json_config.hpp"
#include "render_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace render_test;

TEST(ScanRenderer, FillsTheLaserScanWithLms100Geometry) {
  std::mt19937_64 rng(1);
  LaserScan scan;
  render_scan(wall_world(5.0), Pose2{}, 1'000'000, ScanRenderConfig{}, rng, scan);
  ASSERT_EQ(scan.ranges.size(), 541u);
  ASSERT_EQ(scan.rssi.size(), 541u);
  EXPECT_EQ(scan.utime, 1'000'000);
  EXPECT_EQ(scan.rssi_bits, 16);
  EXPECT_NEAR(scan.start_angle, -135.0 * kDeg, 1e-12);
  EXPECT_NEAR(scan.angle_increment, 0.5 * kDeg, 1e-12);
  EXPECT_NEAR(scan.time_increment, 1.0 / 36000.0, 1e-12);
  EXPECT_NEAR(scan.scan_period, 0.02, 1e-12);
  EXPECT_NEAR(scan.beam_angle(540), 135.0 * kDeg, 1e-9);
  EXPECT_EQ(scan.beam_utime(540), 1'000'000 + 15'000);  // 540 beams at 27.78 us
}

TEST(ScanRenderer, ConfigFileSelects25HzQuarterDegreeScans) {
  const JsonConfig file(nlohmann::json::parse(R"({"render": {
      "num_beams": 1081, "start_angle_deg": -135, "angle_increment_deg": 0.25,
      "scan_frequency_hz": 25, "beam_rate_hz": 36000, "rssi_bits": 8,
      "sensor": {"range_sigma": 0.015, "weak_echo_sigma_factor": 1.5, "range_offset": 0.01,
                 "range_min": 0.05, "range_max": 18, "quantize_to_mm": true, "beam_divergence": 0.015,
                 "beam_exit_diameter": 0.008, "beam_subrays": 7, "echo_merge_distance": 0.3,
                 "detection_limit_remission": 0.1, "detection_limit_range": 18,
                 "rssi_at_detection_limit": 1000, "rssi_per_decade": 7000, "diffuse_rssi_max": 30000,
                 "max_incidence_deg": 87, "retro_rssi_near": 65000, "retro_rssi_drop_per_m": 100,
                 "retro_incidence_exponent": 0.3, "retro_range_bias": 0.0, "tape_rssi_near": 64000,
                 "tape_full_incidence_deg": 40, "tape_cutoff_incidence_deg": 75, "metal_rssi_peak": 64000,
                 "metal_lobe_width_deg": 5, "rssi_coverage_exponent": 0.5, "rssi_sigma": 100,
                 "dazzle_range": 0.1}}})"),
                        "render.json");
  const ScanRenderConfig config = parse_scan_render_config(file, "/render");
  EXPECT_NO_THROW(file.reject_unknown_keys());  // every key above is read
  EXPECT_EQ(config.sensor.beam_subrays, 7);
  EXPECT_NEAR(config.sensor.metal_lobe_width, 5 * kDeg, 1e-12);
  EXPECT_NEAR(config.sensor.range_max, 18.0, 1e-12);
  std::mt19937_64 rng(1);
  LaserScan scan;
  render_scan(wall_world(5.0), Pose2{}, 0, config, rng, scan);
  ASSERT_EQ(scan.ranges.size(), 1081u);
  EXPECT_EQ(scan.rssi_bits, 8);
  EXPECT_NEAR(scan.scan_period, 0.04, 1e-12);
  EXPECT_EQ(scan.beam_utime(1080), 30'000);
  EXPECT_NEAR(scan.ranges[540], 5.01, 0.08);
  EXPECT_LE(*std::max_element(scan.rssi.begin(), scan.rssi.end()), 255);
}

TEST(ScanRenderer, BeamStraightAtWallReturnsItsDistanceWithinNoise) {
  const World world = wall_world(5.0);
  ScanRenderer renderer;
  std::mt19937_64 rng(7);
  LaserScan scan;
  std::vector<double> centre;
  for (int k = 0; k < 400; ++k) {
    renderer.render(world, Pose2{}, 0, rng, scan);
    centre.push_back(scan.ranges[270]);
    for (size_t i = 250; i <= 290; ++i) {
      EXPECT_NEAR(scan.ranges[i], 5.0 / std::cos(scan.beam_angle(i)), 5 * 0.012) << "beam " << i;
    }
  }
  const double mean = std::accumulate(centre.begin(), centre.end(), 0.0) / centre.size();
  double var = 0.0;
  for (double r : centre) var += (r - mean) * (r - mean);
  const double sigma = std::sqrt(var / (centre.size() - 1));
  EXPECT_NEAR(mean, 5.0, 0.003);
  EXPECT_NEAR(sigma, 0.012, 0.002);
}

TEST(ScanRenderer, WeakEchoesAreNoisierUpToTwentyMillimetres) {
  const Lms100ErrorModel m;
  EXPECT_NEAR(range_sigma_for(m, m.rssi_at_detection_limit), 0.020, 1e-12);
  EXPECT_NEAR(range_sigma_for(m, m.rssi_at_detection_limit + m.rssi_per_decade), 0.012, 1e-12);
  EXPECT_NEAR(range_sigma_for(m, 60000.0), 0.012, 1e-12);
  // 10 % remission at 17 m is just above the detection limit.
  const World world = wall_world(17.0, 0.10);
  ScanRenderer renderer;
  std::mt19937_64 rng(3);
  LaserScan scan;
  std::vector<double> centre;
  for (int k = 0; k < 400; ++k) {
    renderer.render(world, Pose2{}, 0, rng, scan);
    if (scan.ranges[270] > 0.0f) centre.push_back(scan.ranges[270]);
  }
  ASSERT_GT(centre.size(), 390u);
  const double mean = std::accumulate(centre.begin(), centre.end(), 0.0) / centre.size();
  double var = 0.0;
  for (double r : centre) var += (r - mean) * (r - mean);
  EXPECT_NEAR(std::sqrt(var / (centre.size() - 1)), 0.0195, 0.0025);
}

TEST(ScanRenderer, SystematicOffsetShiftsEveryRange) {
  ScanRenderConfig config = noise_free_config();
  config.sensor.range_offset = 0.03;
  std::mt19937_64 rng(1);
  LaserScan scan;
  render_scan(wall_world(4.0), Pose2{}, 0, config, rng, scan);
  EXPECT_NEAR(scan.ranges[270], 4.03, 1e-4);
}

TEST(ScanRenderer, RetroRangeBiasShiftsReflectorsButNotWalls) {
  World world = wall_world(6.0);
  add_reflector(world, 1, 3.0, 0.0);
  ScanRenderConfig config = noise_free_config();
  std::mt19937_64 rng(1);
  LaserScan plain;
  LaserScan biased;
  render_scan(world, Pose2{}, 0, config, rng, plain);
  config.sensor.retro_range_bias = 0.02;
  render_scan(world, Pose2{}, 0, config, rng, biased);
  EXPECT_NEAR(biased.ranges[270] - plain.ranges[270], 0.02, 1e-4);
  EXPECT_NEAR(biased.ranges[300] - plain.ranges[300], 0.0, 1e-6);  // +15 deg: the wall
}

TEST(ScanRenderer, ReflectorIsHitByAboutItsWidthOverPointSpacingBeams) {
  for (const double d : {1.5, 2.0, 3.0, 5.0, 8.0}) {
    World world = wall_world(d + 2.0);
    add_reflector(world, 1, d, 0.013);  // off the beam grid's symmetry
    ScanRenderer renderer(noise_free_config());
    std::mt19937_64 rng(3);
    LaserScan scan;
    renderer.render(world, Pose2{}, 0, rng, scan);
    int hits = 0;
    for (const BeamTruth& t : renderer.truth()) hits += t.kind == HitKind::kReflector && t.coverage >= 0.5;
    const double expected = 0.12 / (d * std::tan(0.5 * kDeg));
    EXPECT_NEAR(hits, expected, 1.5) << "at " << d << " m";
  }
}

TEST(ScanRenderer, FullyCoveredReflectorPointsLieOnItsNearSurface) {
  World world = wall_world(6.0);
  add_reflector(world, 1, 2.5, 0.4);
  ScanRenderer renderer(noise_free_config());
  std::mt19937_64 rng(1);
  LaserScan scan;
  renderer.render(world, Pose2{}, 0, rng, scan);
  int checked = 0;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const BeamTruth& t = renderer.truth()[i];
    if (t.kind != HitKind::kReflector || t.coverage < 0.99) continue;
    const Eigen::Vector2d p =
        scan.ranges[i] * Eigen::Vector2d(std::cos(scan.beam_angle(i)), std::sin(scan.beam_angle(i)));
    EXPECT_NEAR((p - Eigen::Vector2d(2.5, 0.4)).norm(), 0.06, 0.003) << "beam " << i;
    ++checked;
  }
  EXPECT_GE(checked, 3);
}

TEST(ScanRenderer, MixedPixelsAppearBetweenForegroundAndBackgroundAtAnEdge) {
  World world = wall_world(3.3);
  // A plate 0.3 m in front of the wall, its edge on the beam axis.
  add_polyline(world, {{3.0, 0.0}, {3.0, -2.0}}, false, SurfaceKind::kDiffuse, 0.5);
  ScanRenderer renderer(noise_free_config());
  std::mt19937_64 rng(5);
  LaserScan scan;
  renderer.render(world, Pose2{}, 0, rng, scan);
  int mixed = 0;
  for (size_t i = 260; i <= 280; ++i) {
    const double x = scan.ranges[i] * std::cos(scan.beam_angle(i));
    if (x > 3.02 && x < 3.28) ++mixed;
  }
  EXPECT_GE(mixed, 1);
  EXPECT_LE(mixed, 3);
  EXPECT_NEAR(scan.ranges[beam_at(scan, -3 * kDeg)] * std::cos(3 * kDeg), 3.0, 1e-3);
  EXPECT_NEAR(scan.ranges[beam_at(scan, 3 * kDeg)] * std::cos(3 * kDeg), 3.3, 1e-3);
}

TEST(ScanRenderer, NoEchoBeyondTwentyMetres) {
  std::mt19937_64 rng(1);
  LaserScan scan;
  render_scan(wall_world(25.0, 1.0), Pose2{}, 0, ScanRenderConfig{}, rng, scan);
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    EXPECT_EQ(scan.ranges[i], 0.0f) << "beam " << i;
    EXPECT_EQ(scan.rssi[i], 0) << "beam " << i;
  }
  render_scan(wall_world(19.0, 0.5), Pose2{}, 0, ScanRenderConfig{}, rng, scan);
  EXPECT_NEAR(scan.ranges[270], 19.0, 0.06);
}

TEST(ScanRenderer, DarkSurfaceFadesOutBeforeTheRangeLimit) {
  std::mt19937_64 rng(1);
  LaserScan scan;
  render_scan(wall_world(17.0, 0.10), Pose2{}, 0, ScanRenderConfig{}, rng, scan);
  EXPECT_NEAR(scan.ranges[270], 17.0, 0.06);  // 10 % is seen to 18 m
  render_scan(wall_world(17.0, 0.05), Pose2{}, 0, ScanRenderConfig{}, rng, scan);
  EXPECT_EQ(scan.ranges[270], 0.0f);
}

TEST(ScanRenderer, BeamsAreCastFromThePoseAtTheirOwnTime) {
  const World world = wall_world(5.0);
  const double speed = 4.0;  // [m/s] towards the wall
  const PoseAtTime moving = [speed](int64_t utime) { return Pose2{speed * utime * 1e-6, 0.0, 0.0}; };
  ScanRenderer renderer(noise_free_config());
  std::mt19937_64 rng(1);
  LaserScan moved;
  LaserScan still;
  renderer.render(world, moving, 0, rng, moved);
  renderer.render(world, Pose2{}, 0, rng, still);
  for (size_t i = 190; i <= 350; ++i) {
    const double t = i / 36000.0;
    EXPECT_NEAR(moved.ranges[i], (5.0 - speed * t) / std::cos(moved.beam_angle(i)), 1e-3) << "beam " << i;
  }
  // Beam 350 (+40 deg) is measured 9.7 ms after beam 0, beam 190 (-40 deg) 5.3 ms:
  // a static renderer would be 3.9 cm and 2.1 cm off along x.
  EXPECT_NEAR(still.ranges[350] - moved.ranges[350], speed * (350 / 36000.0) / std::cos(40 * kDeg), 1e-3);
  EXPECT_NEAR(still.ranges[190] - moved.ranges[190], speed * (190 / 36000.0) / std::cos(40 * kDeg), 1e-3);
}

TEST(ScanRenderer, SameSeedSameScanOtherSeedOtherNoise) {
  World world = wall_world(5.0);
  add_reflector(world, 1, 3.0, 0.5);
  LaserScan a;
  LaserScan b;
  LaserScan c;
  std::mt19937_64 rng_a(42);
  std::mt19937_64 rng_b(42);
  std::mt19937_64 rng_c(43);
  render_scan(world, Pose2{0.1, 0.2, 0.3}, 0, ScanRenderConfig{}, rng_a, a);
  render_scan(world, Pose2{0.1, 0.2, 0.3}, 0, ScanRenderConfig{}, rng_b, b);
  render_scan(world, Pose2{0.1, 0.2, 0.3}, 0, ScanRenderConfig{}, rng_c, c);
  EXPECT_EQ(a.ranges, b.ranges);
  EXPECT_EQ(a.rssi, b.rssi);
  EXPECT_NE(a.ranges, c.ranges);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
