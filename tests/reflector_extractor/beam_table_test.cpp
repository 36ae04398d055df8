#include "reflector_extractor/beam_table.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

LaserScan five_beam_scan() {
  LaserScan scan;
  scan.utime = 1'000'000;
  scan.start_angle = -0.1;
  scan.angle_increment = 0.05;
  scan.time_increment = 1e-4;
  scan.range_min = 0.05;
  scan.range_max = 20.0;
  // no echo, dazzled, echo, beyond range_max, echo exactly at range_min
  scan.ranges = {0.0f, 0.001f, 2.0f, 25.0f, 0.05f};
  scan.rssi = {0, 65535, 46260, 1000, 257};
  scan.rssi_bits = 16;
  return scan;
}

TEST(BeamTable, SentinelRangesBecomeNoEchoAndDazzledOnceAndEchoesKeepTheirRange) {
  BeamTable table;
  make_beam_table(five_beam_scan(), table);
  ASSERT_EQ(table.size(), 5u);
  EXPECT_EQ(table.beams[0].kind, BeamKind::kNoEcho);   // sensor code 0
  EXPECT_EQ(table.beams[1].kind, BeamKind::kDazzled);  // sensor code 1 (0.001 m)
  EXPECT_EQ(table.beams[2].kind, BeamKind::kEcho);
  EXPECT_EQ(table.beams[3].kind, BeamKind::kNoEcho);  // beyond range_max
  EXPECT_EQ(table.beams[4].kind, BeamKind::kEcho);    // range_min itself is an echo
  EXPECT_DOUBLE_EQ(table.beams[2].range, 2.0);
}

TEST(BeamTable, SixteenBitRssiIsOnThe8BitScaleAndEightBitIsKept) {
  LaserScan scan = five_beam_scan();
  BeamTable table;
  make_beam_table(scan, table);
  EXPECT_TRUE(table.has_rssi);
  EXPECT_DOUBLE_EQ(table.beams[1].rssi_8bit, 255.0);
  EXPECT_DOUBLE_EQ(table.beams[2].rssi_8bit, 180.0);
  EXPECT_DOUBLE_EQ(table.beams[4].rssi_8bit, 1.0);
  scan.rssi = {0, 255, 180, 10, 1};
  scan.rssi_bits = 8;
  make_beam_table(scan, table);
  EXPECT_DOUBLE_EQ(table.beams[1].rssi_8bit, 255.0);
  EXPECT_DOUBLE_EQ(table.beams[2].rssi_8bit, 180.0);
}

TEST(BeamTable, RssiOfTheWrongLengthIsNoRssiAtAll) {
  LaserScan scan = five_beam_scan();
  scan.rssi.pop_back();
  BeamTable table;
  make_beam_table(scan, table);
  EXPECT_FALSE(table.has_rssi);
  for (const TableBeam& b : table.beams) EXPECT_EQ(b.rssi_8bit, 0.0);
}

TEST(BeamTable, PointsAndBeamTimesMatchTheScanGeometryBitForBit) {
  const LaserScan scan = five_beam_scan();
  BeamTable table;
  make_beam_table(scan, table);
  for (size_t i = 0; i < scan.ranges.size(); ++i) {
    const double a = scan.beam_angle(i);
    const double r = static_cast<double>(scan.ranges[i]);
    EXPECT_EQ(table.beams[i].point.x(), r * std::cos(a)) << i;
    EXPECT_EQ(table.beams[i].point.y(), r * std::sin(a)) << i;
    EXPECT_EQ(table.beam_utime(i), scan.beam_utime(i)) << i;
  }
}

TEST(BeamTable, ReusedTableFollowsANewScanGeometry) {
  LaserScan scan = five_beam_scan();
  BeamTable table;
  make_beam_table(scan, table);
  scan.start_angle = 0.3;
  make_beam_table(scan, table);
  EXPECT_EQ(table.beams[2].direction.x(), std::cos(scan.beam_angle(2)));
  EXPECT_EQ(table.beams[2].direction.y(), std::sin(scan.beam_angle(2)));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
