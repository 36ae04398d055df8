#include "reflector_extractor/energy_filter.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

BeamTable table_of(const LaserScan& scan) {
  BeamTable table;
  make_beam_table(scan, table);
  return table;
}

LaserScan three_beam_scan(int bits, std::vector<int32_t> rssi) {
  LaserScan scan;
  scan.start_angle = 0.0;
  scan.angle_increment = 0.01;
  scan.ranges = {2.0f, 2.0f, 2.0f};
  scan.rssi = std::move(rssi);
  scan.rssi_bits = bits;
  return scan;
}

TEST(EnergyFilter, SixteenBitRssiIsDividedBy257BeforeThePaperThreshold180) {
  // 180 * 257 = 46260: one count below must fail, the value itself must pass.
  const LaserScan scan = three_beam_scan(16, {46259, 46260, 65535});
  std::vector<uint8_t> high;
  select_high_energy_beams(table_of(scan), 180.0, high);
  EXPECT_EQ(high, (std::vector<uint8_t>{0, 1, 1}));
  EXPECT_DOUBLE_EQ(table_of(scan).beams[2].rssi_8bit, 255.0);
}

TEST(EnergyFilter, EightBitRssiIsComparedAsIs) {
  const LaserScan scan = three_beam_scan(8, {179, 180, 255});
  std::vector<uint8_t> high;
  select_high_energy_beams(table_of(scan), 180.0, high);
  EXPECT_EQ(high, (std::vector<uint8_t>{0, 1, 1}));
}

TEST(EnergyFilter, NoEchoAndDazzledBeamsNeverPassEvenWhenBright) {
  LaserScan scan = three_beam_scan(16, {65535, 65535, 65535});
  scan.ranges = {0.0f, 0.001f, 3.0f};
  std::vector<uint8_t> high;
  select_high_energy_beams(table_of(scan), 180.0, high);
  EXPECT_EQ(high, (std::vector<uint8_t>{0, 0, 1}));
}

TEST(EnergyFilter, ScanWithoutRssiSelectsNothing) {
  LaserScan scan = three_beam_scan(0, {});
  std::vector<uint8_t> high;
  select_high_energy_beams(table_of(scan), 180.0, high);
  EXPECT_EQ(high, (std::vector<uint8_t>{0, 0, 0}));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
