// The matcher's line of sight (three beams to a reflector's near side, map occluders) against
// what the LMS100 renderer really lights in the demo hall: the study's "with walls" runs rely on
// the two agreeing.

#include "reflector_matcher/occluder_grid.hpp"
#include "reflector_matcher/reflector_visibility.hpp"
#include "study_map.hpp"
#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"
#include "world_renderer/world_visibility.hpp"

#include <gtest/gtest.h>

#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(OccluderSight, NoReflectorTheRendererLightsIsHiddenAndFewInPlainViewGetNoBeam) {
  const sim::World world = sim::load_world(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json");
  const ReflectorMap map = study_map(world, "", "world");
  const OccluderGrid occluders(map.occluders);
  sim::ScanRenderConfig render;
  render.sensor.range_sigma = 0.0;
  sim::ScanRenderer renderer(render);
  std::mt19937_64 rng(1);
  LaserScan scan;
  // [LineOfSight][renderer: no beam, only edge beams, >= 2 beams at least half on it]
  int table[3][3] = {};
  for (double x = 0.5; x < 20.0; x += 0.5) {
    for (double y = 0.5; y < 12.0; y += 0.5) {
      if (!world.is_drivable({x, y}) || sim::clearance(world, {x, y}) < 0.3) continue;
      for (double heading : {0.0, M_PI}) {  // 270 deg each: all around
        const Pose2 laser{x, y, heading};
        renderer.render(world, laser, 1'700'000'000'000'000, rng, scan);
        std::map<int, int> beams, good_beams;
        for (const auto& t : renderer.truth()) {
          if (t.kind != sim::HitKind::kReflector) continue;
          ++beams[t.id];
          good_beams[t.id] += t.coverage >= 0.5;
        }
        for (const MapReflector& r : map.reflectors) {
          const Eigen::Vector2d laser_p = laser.inverse() * r.map_p_center;
          // Within the missed penalty's 8 m, clear of the field of view's edge.
          if (laser_p.norm() > 8.0 || std::abs(std::atan2(laser_p.y(), laser_p.x())) > 0.75 * M_PI - 0.05)
            continue;
          const int rendered = good_beams[r.id] >= 2 ? 2 : (beams[r.id] > 0 ? 1 : 0);
          ++table[static_cast<int>(line_of_sight(occluders, laser.translation(), r))][rendered];
        }
      }
    }
  }
  const auto clear = static_cast<int>(LineOfSight::kClear), hidden = static_cast<int>(LineOfSight::kBlocked);
  std::printf("clear: %d no beam, %d edge, %d lit; partial: %d/%d/%d; hidden: %d/%d/%d\n", table[0][0],
              table[0][1], table[0][2], table[1][0], table[1][1], table[1][2], table[2][0], table[2][1],
              table[2][2]);
  EXPECT_EQ(table[hidden][2], 0);
  EXPECT_GT(table[hidden][0], 2000);
  // Clear but dark: shadowed by a nearer reflector (the matcher checks that separately).
  EXPECT_LT(table[clear][0], table[clear][2] / 200);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
