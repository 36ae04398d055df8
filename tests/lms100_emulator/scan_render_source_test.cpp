#include "lms100_emulator/scan_render_source.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc::sim {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;

std::shared_ptr<const World> wall_and_reflector_world() {
  auto world = std::make_shared<World>();
  add_polyline(*world, {{5.0, -30.0}, {5.0, 30.0}}, false, SurfaceKind::kDiffuse, 0.5);
  MapReflector r;
  r.id = 1;
  r.map_p_center = {2.0, 2.0 * std::tan(20 * kDeg)};
  world->reflectors.reflectors.push_back(r);
  return world;
}

ScanRequest lms100_request(int rssi_bits) {
  ScanRequest request;
  request.first_beam_utime = 5'000'000;
  request.num_beams = 541;
  request.start_angle_rad = -135 * kDeg;
  request.angle_increment_rad = 0.5 * kDeg;
  request.rssi_bits = rssi_bits;
  return request;
}

TEST(RenderedScanSource, FillsMillimetresAndSixteenBitRssi) {
  ScanSource source = make_rendered_scan_source(
      wall_and_reflector_world(), [](int64_t) { return Pose2{}; }, {}, 1);
  std::vector<uint16_t> dist(541, 0);
  std::vector<uint16_t> rssi(541, 0);
  source(lms100_request(16), dist, rssi);
  EXPECT_NEAR(dist[270], 5000, 60);
  EXPECT_GT(rssi[270], 1000);
  EXPECT_LT(rssi[270], 30000);
  const size_t reflector_beam = 270 + 40;  // +20 deg
  EXPECT_NEAR(dist[reflector_beam], 2.0 / std::cos(20 * kDeg) * 1000 - 60, 60);
  EXPECT_GE(rssi[reflector_beam], 60000);
  EXPECT_EQ(dist[0], 0);  // -135 deg: parallel to the wall, nothing there
}

TEST(RenderedScanSource, EightBitRssiAndNoRssiFollowTheRequest) {
  ScanSource source = make_rendered_scan_source(
      wall_and_reflector_world(), [](int64_t) { return Pose2{}; }, {}, 1);
  std::vector<uint16_t> dist(541, 0);
  std::vector<uint16_t> rssi(541, 0);
  source(lms100_request(8), dist, rssi);
  for (uint16_t v : rssi) EXPECT_LE(v, 255);
  EXPECT_GE(rssi[310], 180);
  std::vector<uint16_t> no_rssi;
  source(lms100_request(0), dist, no_rssi);
  EXPECT_NEAR(dist[270], 5000, 60);
}

TEST(RenderedScanSource, AsksThePoseAtEachBeamTime) {
  std::vector<int64_t> asked;
  ScanRenderConfig config;
  config.sensor.range_sigma = 0.0;
  ScanSource source = make_rendered_scan_source(
      wall_and_reflector_world(),
      [&asked](int64_t utime) {
        asked.push_back(utime);
        return Pose2{(utime - 5'000'000) * 1e-6 * 2.0, 0.0, 0.0};  // 2 m/s towards the wall
      },
      config, 1);
  std::vector<uint16_t> dist(541, 0);
  std::vector<uint16_t> rssi(541, 0);
  source(lms100_request(16), dist, rssi);
  ASSERT_EQ(asked.size(), 541u);
  EXPECT_EQ(asked.front(), 5'000'000);
  EXPECT_EQ(asked.back(), 5'015'000);
  EXPECT_NEAR(dist[270], 5000 - 2.0 * 7.5, 1.5);  // beam 270 is measured 7.5 ms into the scan
}

TEST(RenderedScanSource, DazzledAndOutOfRangeUseTheSensorCodes) {
  auto world = std::make_shared<World>();
  MapReflector r;
  r.id = 1;
  r.map_p_center = {0.2, 0.0};
  world->reflectors.reflectors.push_back(r);
  add_polyline(*world, {{-25.0, -30.0}, {-25.0, 30.0}}, false, SurfaceKind::kDiffuse, 0.9);
  ScanRenderConfig config;
  config.sensor.dazzle_range = 0.3;
  ScanSource source = make_rendered_scan_source(
      world, [](int64_t) { return Pose2{}; }, config, 1);
  std::vector<uint16_t> dist(541, 7);
  std::vector<uint16_t> rssi(541, 7);
  source(lms100_request(16), dist, rssi);
  EXPECT_EQ(dist[270], 1);
  EXPECT_EQ(rssi[270], 65535);
  EXPECT_EQ(dist[0], 0);  // the wall behind at 25 m is out of range
  EXPECT_EQ(rssi[0], 0);
}

TEST(RenderedScanSource, ThrowingPoseGivesAScanWithoutEchoes) {
  ScanSource source = make_rendered_scan_source(
      wall_and_reflector_world(), [](int64_t) -> Pose2 { throw std::runtime_error("no pose"); }, {}, 1);
  std::vector<uint16_t> dist(541, 7);
  std::vector<uint16_t> rssi(541, 7);
  source(lms100_request(16), dist, rssi);
  for (size_t i = 0; i < dist.size(); ++i) {
    EXPECT_EQ(dist[i], 0);
    EXPECT_EQ(rssi[i], 0);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::sim
