// The emulator's rendered scans with the error model's rssi_scale 8bit_in_16bit: the
// 16-bit requests carry 0..255 (the quirk), the 8-bit requests stay the 8-bit scale.
#include "lms100_emulator/scan_render_source.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kQuirkDeg = M_PI / 180.0;

std::shared_ptr<const World> quirk_world() {
  auto world = std::make_shared<World>();
  add_polyline(*world, {{5.0, -30.0}, {5.0, 30.0}}, false, SurfaceKind::kDiffuse, 0.5);
  MapReflector r;
  r.id = 1;
  r.map_p_center = {2.0, 2.0 * std::tan(20 * kQuirkDeg)};
  world->reflectors.reflectors.push_back(r);
  return world;
}

ScanRequest quirk_request(int rssi_bits) {
  ScanRequest request;
  request.first_beam_utime = 5'000'000;
  request.num_beams = 541;
  request.start_angle_rad = -135 * kQuirkDeg;
  request.angle_increment_rad = 0.5 * kQuirkDeg;
  request.rssi_bits = rssi_bits;
  return request;
}

TEST(RenderedScanSourceRssiScale, EightBitValuesInTheSixteenBitChannel) {
  ScanRenderConfig config;
  config.sensor.rssi_scale = RssiScale::k8BitIn16Bit;
  ScanSource source = make_rendered_scan_source(
      quirk_world(), [](int64_t) { return Pose2{}; }, config, 1);
  std::vector<uint16_t> dist(541, 0);
  std::vector<uint16_t> rssi(541, 0);
  source(quirk_request(16), dist, rssi);
  EXPECT_LE(*std::max_element(rssi.begin(), rssi.end()), 255);
  EXPECT_GE(rssi[310], 230);  // the reflector at +20 deg: the top of the 8-bit scale
  EXPECT_GT(rssi[270], 3);    // the wall: dim but not gone
  source(quirk_request(8), dist, rssi);
  EXPECT_LE(*std::max_element(rssi.begin(), rssi.end()), 255);
  EXPECT_GE(rssi[310], 230);  // not divided twice
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
