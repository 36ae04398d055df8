#include "reflector_extractor/adaptive_breakpoint.hpp"

#include "reflector_extractor/energy_filter.hpp"
#include "scenes.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;

TEST(AdaptiveBreakpoint, MaxDistanceFollowsEquation3) {
  AdaptiveBreakpointClusterer clusterer;  // lambda 10 deg, sigma_r 0.012 m
  // 5 m * sin(0.5 deg) / sin(9.5 deg) + 0.036 = 0.26436 + 0.036
  EXPECT_NEAR(clusterer.max_distance(5.0, 0.5 * kDeg), 0.30036, 2e-5);
  EXPECT_NEAR(clusterer.max_distance(0.0, 0.5 * kDeg), 0.036, 1e-12);
}

std::vector<BeamCluster> cluster_scene(const SyntheticScene& scene, uint32_t seed,
                                       AdaptiveBreakpointConfig config = {}) {
  std::mt19937 rng(seed);
  const LaserScan scan = render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
  BeamTable table;
  make_beam_table(scan, table);
  std::vector<uint8_t> high;
  select_high_energy_beams(table, 180.0, high);
  std::vector<BeamCluster> clusters;
  AdaptiveBreakpointClusterer(config).cluster(table, high, clusters);
  return clusters;
}

TEST(AdaptiveBreakpoint, TwoReflectors30cmApartSideBySideGiveTwoClusters) {
  for (double range : {1.0, 3.0, 5.0, 8.0}) {
    for (uint32_t seed = 0; seed < 20; ++seed) {
      SyntheticScene scene;
      const double half_angle = std::atan2(0.15, range);
      scene.cylinders = {test::cylinder_at(range, -half_angle), test::cylinder_at(range, half_angle)};
      scene.segments = {test::dull_wall_behind(range, 0.0)};
      ASSERT_EQ(cluster_scene(scene, seed).size(), 2u) << "range " << range << " seed " << seed;
    }
  }
}

TEST(AdaptiveBreakpoint, TwoReflectors30cmApartOneBehindTheOtherGiveTwoClusters) {
  // Same bearing side by side is handled by the gap rule; this one needs D_max itself:
  // the second reflector peeks out 0.3 m farther away with no dull beam in between.
  for (double range : {1.0, 2.0, 3.0}) {
    for (uint32_t seed = 0; seed < 20; ++seed) {
      SyntheticScene scene;
      scene.cylinders = {test::cylinder_at(range, 0.0),
                         test::cylinder_at(range + 0.3, std::atan2(0.1, range))};
      ASSERT_EQ(cluster_scene(scene, seed).size(), 2u) << "range " << range << " seed " << seed;
    }
  }
}

TEST(AdaptiveBreakpoint, OneReflectorStaysOneClusterFrom05To12m) {
  int trials = 0;
  for (double range = 0.5; range <= 12.0; range += 0.5) {
    for (uint32_t seed = 0; seed < 20; ++seed) {
      SyntheticScene scene;
      scene.cylinders = {test::cylinder_at(range, 0.3 * seed * kDeg)};
      scene.segments = {test::dull_wall_behind(range, 0.0)};
      ASSERT_LE(cluster_scene(scene, seed).size(), 1u) << "range " << range << " seed " << seed;
      ++trials;
    }
  }
  EXPECT_EQ(trials, 24 * 20);
}

TEST(AdaptiveBreakpoint, PaperModeClustersAcrossDullBeamsButDefaultDoesNot) {
  LaserScan scan;
  scan.start_angle = 0.0;
  scan.angle_increment = 0.5 * kDeg;
  scan.ranges = {2.0f, 2.0f, 2.0f, 2.0f};
  BeamTable table;
  make_beam_table(scan, table);
  std::vector<uint8_t> selected = {1, 1, 0, 1};
  std::vector<BeamCluster> clusters;
  AdaptiveBreakpointClusterer().cluster(table, selected, clusters);
  EXPECT_EQ(clusters.size(), 2u);
  AdaptiveBreakpointConfig paper;
  paper.max_gap_beams = -1;
  AdaptiveBreakpointClusterer(paper).cluster(table, selected, clusters);
  ASSERT_EQ(clusters.size(), 1u);
  EXPECT_EQ(clusters[0].first, 0);
  EXPECT_EQ(clusters[0].last, 3);
  EXPECT_EQ(clusters[0].num_selected, 3);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
