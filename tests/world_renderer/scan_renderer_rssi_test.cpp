// The scan renderer's RSSI: reflectors bright and walls dim, falling with range and
// incidence, partial hits by coverage, tape and metal by incidence, 8-bit scale.
#include "world_renderer/scan_renderer.hpp"

#include "render_scenes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace render_test;

TEST(ScanRenderer, ReflectorBeamsAreBrightAndWallBeamsDim) {
  World world = wall_world(6.0);
  add_reflector(world, 1, 3.0, 0.0);
  ScanRenderer renderer;
  std::mt19937_64 rng(5);
  LaserScan scan;
  renderer.render(world, Pose2{}, 0, rng, scan);
  EXPECT_GE(scan.rssi[270], 60000);
  EXPECT_NEAR(scan.ranges[270], 2.94, 0.05);
  for (size_t i = 180; i <= 360; ++i) {
    if (renderer.truth()[i].kind != HitKind::kDiffuse) continue;
    EXPECT_GE(scan.rssi[i], 2000) << "beam " << i;
    EXPECT_LE(scan.rssi[i], 20000) << "beam " << i;
  }
}

TEST(ScanRenderer, DiffuseRssiFallsWithRangeAndIncidence) {
  const Lms100ErrorModel m;
  EXPECT_GT(diffuse_rssi(m, 0.5, 1.0, 2.0), diffuse_rssi(m, 0.5, 1.0, 8.0));
  EXPECT_GT(diffuse_rssi(m, 0.5, 1.0, 4.0), diffuse_rssi(m, 0.5, std::cos(60 * kDeg), 4.0));
  EXPECT_NEAR(diffuse_rssi(m, 0.10, 1.0, 18.0), m.rssi_at_detection_limit, 1e-6);
  EXPECT_EQ(diffuse_rssi(m, 0.5, std::cos(89 * kDeg), 4.0), 0.0);  // grazing: no echo
  EXPECT_LT(diffuse_rssi(m, 0.9, 1.0, 0.5), kPaperRssiThreshold16);
  EXPECT_GE(retro_reflector_rssi(m, 1.0, 20.0), 60000.0);
}

TEST(ScanRenderer, EdgeBeamsOfAReflectorAreDimmerThanItsCentre) {
  World world = wall_world(5.0);
  add_reflector(world, 1, 2.0, 0.0);
  ScanRenderer renderer(noise_free_config());
  std::mt19937_64 rng(5);
  LaserScan scan;
  renderer.render(world, Pose2{}, 0, rng, scan);
  std::vector<int32_t> reflector_rssi;
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    if (renderer.truth()[i].kind == HitKind::kReflector) reflector_rssi.push_back(scan.rssi[i]);
  }
  ASSERT_GE(reflector_rssi.size(), 7u);
  EXPECT_GE(reflector_rssi[reflector_rssi.size() / 2], 60000);
  EXPECT_LT(reflector_rssi.front(), 0.8 * reflector_rssi[reflector_rssi.size() / 2]);
  EXPECT_LT(reflector_rssi.back(), 0.8 * reflector_rssi[reflector_rssi.size() / 2]);
}

TEST(ScanRenderer, PartialHitRssiFollowsCoverageToTheConfiguredPower) {
  // Tape whose edge cuts the centre beam's spot; nothing behind it.
  World world;
  add_polyline(world, {{4.0, 0.001}, {4.0, 1.0}}, false, SurfaceKind::kReflectiveTape, 0.8);
  for (const double exponent : {1.0, 0.5}) {
    ScanRenderConfig config = noise_free_config();
    config.sensor.rssi_coverage_exponent = exponent;
    ScanRenderer renderer(config);
    std::mt19937_64 rng(1);
    LaserScan scan;
    renderer.render(world, Pose2{}, 0, rng, scan);
    const double coverage = renderer.truth()[270].coverage;
    ASSERT_GT(coverage, 0.3);
    ASSERT_LT(coverage, 0.6);
    const double full = tape_rssi(config.sensor, 0.8, 1.0, 4.0);
    EXPECT_NEAR(scan.rssi[270], full * std::pow(coverage, exponent), 300) << "exponent " << exponent;
  }
}

TEST(ScanRenderer, TapeIsBrightUntilSteepIncidenceMetalOnlyNearNormal) {
  for (const auto& [surface, incidence_deg, bright] :
       std::vector<std::tuple<SurfaceKind, double, bool>>{{SurfaceKind::kReflectiveTape, 0.0, true},
                                                          {SurfaceKind::kReflectiveTape, 30.0, true},
                                                          {SurfaceKind::kReflectiveTape, 80.0, false},
                                                          {SurfaceKind::kMetal, 0.0, true},
                                                          {SurfaceKind::kMetal, 20.0, false},
                                                          {SurfaceKind::kMetal, 45.0, false}}) {
    World world;
    // A 1 m strip through (4, 0), tilted so the centre beam meets it at incidence_deg.
    const double a = incidence_deg * kDeg;
    const Eigen::Vector2d along(-std::sin(a), std::cos(a));
    add_polyline(world, {Eigen::Vector2d(4, 0) - 0.5 * along, Eigen::Vector2d(4, 0) + 0.5 * along}, false,
                 surface, surface == SurfaceKind::kMetal ? 0.05 : 0.8);
    ScanRenderer renderer(noise_free_config());
    std::mt19937_64 rng(1);
    LaserScan scan;
    renderer.render(world, Pose2{}, 0, rng, scan);
    if (bright) {
      EXPECT_GT(scan.rssi[270], kPaperRssiThreshold16)
          << surface_kind_name(surface) << " at " << incidence_deg;
    } else {
      EXPECT_LT(scan.rssi[270], 30000) << surface_kind_name(surface) << " at " << incidence_deg;
    }
  }
}

TEST(ScanRenderer, EightBitRssiPassesThePaperThresholdOnReflectorsOnly) {
  World world = wall_world(6.0, 0.9);
  add_reflector(world, 1, 3.0, 0.0);
  ScanRenderConfig config;
  config.rssi_bits = 8;
  ScanRenderer renderer(config);
  std::mt19937_64 rng(9);
  LaserScan scan;
  renderer.render(world, Pose2{}, 0, rng, scan);
  EXPECT_EQ(scan.rssi_bits, 8);
  for (size_t i = 0; i < scan.rssi.size(); ++i) {
    EXPECT_LE(scan.rssi[i], 255);
    if (renderer.truth()[i].kind == HitKind::kDiffuse) {
      EXPECT_LT(scan.rssi[i], 180) << "beam " << i;
    }
  }
  EXPECT_GE(scan.rssi[270], 180);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
