#include "lms100_driver/scan_conversion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "lms100_driver/lmd_scandata_parser.hpp"
#include "telegram_fixtures.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kDeg = M_PI / 180.0;

TEST(ScanConversion, RealLms111ScanBecomesLaserFrameMetres) {
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(test::read_telegram_payload("lms111_cola_a_scan.txt"), d).ok());
  LaserScan s;
  const ParseResult r = to_laser_scan(d, s);
  ASSERT_TRUE(r.ok()) << r.error;
  ASSERT_EQ(s.ranges.size(), 541u);
  EXPECT_NEAR(s.start_angle, -135.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.beam_angle(540), 135.0 * kDeg, 1e-12);
  EXPECT_NEAR(s.angle_increment, 0.5 * kDeg, 1e-12);
  EXPECT_NEAR(s.time_increment, 1.0 / 36000.0, 1e-12);
  EXPECT_NEAR(s.scan_period, 0.02, 1e-12);
  EXPECT_FLOAT_EQ(s.ranges[0], 0.126F);
  EXPECT_FLOAT_EQ(s.ranges[1], 0.130F);
  EXPECT_TRUE(s.rssi.empty());
  EXPECT_EQ(s.rssi_bits, 0);
  EXPECT_EQ(s.serial_number, 0x8D4C04u);
  EXPECT_EQ(s.scan_counter, 0x37u);
}

TEST(ScanConversion, NoEchoAndDazzledCodesAreKeptAsMarkers) {
  LmdScanData d;
  ASSERT_TRUE(
      parse_lmd_scandata(test::make_scan_telegram({0, 1, 16, 20000}, {0, 65535, 10, 64800}, 16), d).ok());
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_EQ(s.ranges[0], 0.0F);
  EXPECT_EQ(s.ranges[1], 0.001F);
  EXPECT_FLOAT_EQ(s.ranges[2], 0.016F);
  EXPECT_FLOAT_EQ(s.ranges[3], 20.0F);
  EXPECT_EQ(s.rssi_bits, 16);
  EXPECT_EQ(s.rssi, (std::vector<int32_t>{0, 65535, 10, 64800}));
}

TEST(ScanConversion, EightBitRssiComesFromThe8BitBlock) {
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(test::make_scan_telegram({500, 600}, {254, 255}, 8), d).ok());
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_EQ(s.rssi_bits, 8);
  EXPECT_EQ(s.rssi, (std::vector<int32_t>{254, 255}));
}

TEST(ScanConversion, ScaleFactorAndOffsetAreApplied) {
  LmdScanData d;
  std::string t = test::make_scan_telegram({500, 600}, {}, 0);
  t.replace(t.find("3F800000 00000000"), 17, "40000000 41200000");  // scale 2.0, offset 10 mm
  ASSERT_TRUE(parse_lmd_scandata(t, d).ok());
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_FLOAT_EQ(s.ranges[0], 1.010F);
  EXPECT_FLOAT_EQ(s.ranges[1], 1.210F);
}

TEST(ScanConversion, TwentyFiveHertzQuarterDegreeTiming) {
  LmdScanData d;
  std::string t = test::make_scan_telegram({500, 600}, {}, 0);
  t.replace(t.find(" 1388 168 "), 10, " 9C4 168 ");
  t.replace(t.find("FFF92230 1388"), 13, "FFF92230 9C4");
  ASSERT_TRUE(parse_lmd_scandata(t, d).ok());
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_NEAR(s.scan_period, 0.04, 1e-12);
  EXPECT_NEAR(s.angle_increment, 0.25 * kDeg, 1e-12);
}

TEST(ScanConversion, MissingDistOrMismatchedRssiOrNanScaleIsAnError) {
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(test::make_scan_telegram({500, 600}, {1, 2}, 16), d).ok());
  LaserScan s;
  d.channels16[1].values.pop_back();
  EXPECT_FALSE(to_laser_scan(d, s).ok());
  d.channels16[1].values.push_back(2);
  d.channels16[0].scale = std::nanf("");
  EXPECT_FALSE(to_laser_scan(d, s).ok());
  d.channels16[0].name = "DIST2";
  EXPECT_FALSE(to_laser_scan(d, s).ok());
  d.channels16[0].name = "DIST1";
  d.channels16[0].scale = 1.0F;
  d.measurement_frequency_1e1khz = 0;
  EXPECT_FALSE(to_laser_scan(d, s).ok());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
