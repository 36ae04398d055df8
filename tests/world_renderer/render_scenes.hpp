#pragma once
// Small worlds and settings shared by the scan renderer's tests.

#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world.hpp"

#include <cmath>

namespace refloc::sim::render_test {

constexpr double kDeg = M_PI / 180.0;
constexpr double kPaperRssiThreshold16 = 180.0 * 257.0;  // the paper's 8-bit energy threshold 180

inline World wall_world(double wall_x, double remission = 0.5) {
  World world;
  add_polyline(world, {{wall_x, -30.0}, {wall_x, 30.0}}, false, SurfaceKind::kDiffuse, remission);
  return world;
}

inline void add_reflector(World& world, int id, double x, double y) {
  MapReflector r;
  r.id = id;
  r.map_p_center = {x, y};
  world.reflectors.reflectors.push_back(r);
}

inline ScanRenderConfig noise_free_config() {
  ScanRenderConfig c;
  c.sensor.range_sigma = 0.0;
  c.sensor.rssi_sigma = 0.0;
  c.sensor.quantize_to_mm = false;
  return c;
}

inline size_t beam_at(const LaserScan& scan, double angle) {
  return static_cast<size_t>(std::lround((angle - scan.start_angle) / scan.angle_increment));
}

}  // namespace refloc::sim::render_test
