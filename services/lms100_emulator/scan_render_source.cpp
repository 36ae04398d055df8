#include "lms100_emulator/scan_render_source.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace refloc::sim {

void code_scan_for_wire(const LaserScan& scan, int rssi_bits, std::vector<uint16_t>& dist_mm,
                        std::vector<uint16_t>& rssi) {
  const size_t n = std::min(scan.ranges.size(), dist_mm.size());
  for (size_t i = 0; i < n; ++i) {
    const double range = scan.ranges[i];
    uint16_t mm = 0;
    if (range > 0.0 && range < 0.0015) {
      mm = 1;  // dazzled
    } else if (range > 0.0) {
      mm = static_cast<uint16_t>(std::clamp(std::lround(range * 1000.0), 16L, 65535L));
    }
    dist_mm[i] = mm;
    if (i >= rssi.size()) continue;
    const int32_t rssi16 = i < scan.rssi.size() ? scan.rssi[i] : 0;
    rssi[i] = static_cast<uint16_t>(std::clamp(rssi_for_bits(rssi16, rssi_bits), 0, 65535));
  }
}

ScanSource make_rendered_scan_source(std::shared_ptr<const World> world, PoseAtTime map_T_laser_at,
                                     const ScanRenderConfig& config, uint64_t seed) {
  struct State {
    std::shared_ptr<const World> world;
    PoseAtTime map_T_laser_at;
    ScanRenderer renderer;
    std::mt19937_64 rng;
    LaserScan scan;
  };
  ScanRenderConfig render_config = config;
  render_config.rssi_bits = 16;  // converted per request
  // A sensor with 8-bit values in its 16-bit channel: only the 16-bit requests carry the quirk.
  const Lms100ErrorModel reporting = config.sensor;
  render_config.sensor.rssi_scale = RssiScale::k16Bit;
  auto state = std::make_shared<State>(State{
      std::move(world), std::move(map_T_laser_at), ScanRenderer(render_config), std::mt19937_64(seed), {}});
  return [state, reporting](const ScanRequest& request, std::vector<uint16_t>& dist_mm,
                            std::vector<uint16_t>& rssi) {
    ScanGeometry g = state->renderer.config().geometry;
    g.num_beams = std::min<int>(request.num_beams, static_cast<int>(dist_mm.size()));
    g.start_angle = request.start_angle_rad;
    g.angle_increment = request.angle_increment_rad;
    g.time_increment = request.time_increment_s;
    state->renderer.set_geometry(g);
    try {
      state->renderer.render(*state->world, state->map_T_laser_at, request.first_beam_utime, state->rng,
                             state->scan);
    } catch (...) {
      std::fill(dist_mm.begin(), dist_mm.end(), 0);
      std::fill(rssi.begin(), rssi.end(), 0);
      return;
    }
    code_scan_for_wire(state->scan, request.rssi_bits, dist_mm, rssi);
    if (request.rssi_bits == 16 && reporting.rssi_scale != RssiScale::k16Bit) {
      for (uint16_t& value : rssi) value = static_cast<uint16_t>(reported_rssi16(reporting, value));
    }
  };
}

}  // namespace refloc::sim
