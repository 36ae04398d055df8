#include "world_renderer/scan_render_index.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

/// Render with and without the candidate index from the same RNG state.
void expect_same_scan(const World& world, const PoseAtTime& pose_at, int64_t utime, uint64_t seed) {
  ScanRenderer indexed;
  ScanRenderer brute;
  brute.set_brute_force(true);
  std::mt19937_64 rng_a(seed);
  std::mt19937_64 rng_b(seed);
  LaserScan a;
  LaserScan b;
  indexed.render(world, pose_at, utime, rng_a, a);
  brute.render(world, pose_at, utime, rng_b, b);
  ASSERT_EQ(a.ranges.size(), b.ranges.size());
  for (size_t i = 0; i < a.ranges.size(); ++i) {
    ASSERT_EQ(a.ranges[i], b.ranges[i]) << "beam " << i << " seed " << seed;
    ASSERT_EQ(a.rssi[i], b.rssi[i]) << "beam " << i << " seed " << seed;
  }
}

TEST(BeamCandidateIndex, GivesTheSameScansAsTestingEverything) {
  const World world = load_world(kConfigDir + "world_demo.json");
  std::mt19937_64 pick(5);
  std::uniform_real_distribution<double> x(0.3, 19.7);
  std::uniform_real_distribution<double> y(0.3, 11.7);
  std::uniform_real_distribution<double> heading(-M_PI, M_PI);
  std::uniform_real_distribution<double> speed(-2.0, 2.0);
  for (uint64_t k = 0; k < 60; ++k) {
    const Pose2 start{x(pick), y(pick), heading(pick)};
    const double vx = speed(pick);
    const double vy = speed(pick);
    const double wz = 3.0 * speed(pick);  // up to 6 rad/s: a fast spin during the 15 ms sweep
    expect_same_scan(
        world, [start](int64_t) { return start; }, 0, k);
    expect_same_scan(
        world,
        [=](int64_t utime) {
          const double t = utime * 1e-6;
          return Pose2{start.x + vx * t, start.y + vy * t, start.theta + wz * t};
        },
        0, k);
  }
}

TEST(BeamCandidateIndex, CloseObjectsAndWrapAroundAreCandidatesEverywhereTheyCanBeHit) {
  // A reflector touching the sensor, a wall right behind it (across the +-180 deg cut).
  World world;
  MapReflector r;
  r.id = 1;
  r.map_p_center = {0.08, 0.0};
  world.reflectors.reflectors.push_back(r);
  add_polyline(world, {{-1.0, -3.0}, {-1.0, 3.0}, {4.0, 3.0}}, false, SurfaceKind::kDiffuse, 0.5);
  for (uint64_t seed = 0; seed < 5; ++seed) {
    const double theta = M_PI - 0.3 * static_cast<double>(seed);
    expect_same_scan(
        world,
        [theta](int64_t) {
          return Pose2{0.0, 0.0, theta};
        },
        0, seed);
  }
}

TEST(BeamCandidateIndex, KeepsFewCandidatesPerBeamInTheDemoHall) {
  const World world = load_world(kConfigDir + "world_demo.json");
  ScanRenderer renderer;
  BeamCandidateIndex index;
  const std::vector<Pose2> poses(541, Pose2{6.7, 2.2, 0.3});
  index.build(world, poses, -135.0 * M_PI / 180.0, 0.5 * M_PI / 180.0, renderer.profile(), 20.5);
  const double per_beam = static_cast<double>(index.size()) / 541.0;
  const double everything = static_cast<double>(world.reflectors.reflectors.size() + world.segments.size());
  EXPECT_LT(per_beam, 0.25 * everything) << per_beam << " of " << everything;
}

TEST(BeamCandidateIndex, ListingTheReflectorsInReachGivesTheSameCandidates) {
  // 200 reflectors over 60 m x 60 m; the listed ones are those within reach of the sensor
  // (what refloc-plan takes from a grid query), the candidates must be build()'s exactly.
  World world;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(0.0, 60.0);
  for (int i = 0; i < 200; ++i) {
    MapReflector r;
    r.id = i + 1;
    r.map_p_center = {coordinate(rng), coordinate(rng)};
    world.reflectors.reflectors.push_back(r);
  }
  add_polyline(world, {{0, 0}, {60, 0}, {60, 60}, {0, 60}}, true, SurfaceKind::kDiffuse, 0.5);
  ScanRenderer renderer;
  const double reach = 20.0;
  for (int k = 0; k < 10; ++k) {
    const std::vector<Pose2> poses(541, Pose2{coordinate(rng), coordinate(rng), 0.6 * k});
    std::vector<int> near;
    for (size_t i = 0; i < world.reflectors.reflectors.size(); ++i) {
      const double d = (world.reflectors.reflectors[i].map_p_center - poses[0].translation()).norm();
      if (d <= reach + 0.06 + renderer.profile().half_exit_diameter + 0.01)
        near.push_back(static_cast<int>(i));
    }
    ASSERT_LT(near.size(), world.reflectors.reflectors.size());
    BeamCandidateIndex all, listed;
    all.build(world, poses, -135.0 * M_PI / 180.0, 0.5 * M_PI / 180.0, renderer.profile(), reach);
    listed.build(world, near, poses, -135.0 * M_PI / 180.0, 0.5 * M_PI / 180.0, renderer.profile(), reach);
    ASSERT_EQ(all.size(), listed.size());
    for (size_t b = 0; b < 541; ++b) {
      const BeamCandidates a = all.candidates(b), l = listed.candidates(b);
      ASSERT_TRUE(std::equal(a.begin, a.end, l.begin, l.end)) << "pose " << k << " beam " << b;
    }
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
