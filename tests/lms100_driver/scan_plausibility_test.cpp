// The driver's plausibility rules for scan headers, one test per rule, and the reserved
// distance codes: real LMS1xx telegrams pass, every falsified field is refused and named.

#include "lms100_driver/scan_plausibility.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"
#include "telegram_fixtures.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

LmdScanData lms100_scan(size_t beams = 541) {
  LmdScanData d;
  EXPECT_TRUE(
      parse_lmd_scandata(test::make_scan_telegram(std::vector<unsigned>(beams, 2000), {}, 0), d).ok());
  return d;
}

LmdChannel& dist1(LmdScanData& d) { return d.channels16.at(0); }  // make_scan_telegram: DIST1 first

TEST(ScanPlausibility, RealLms111TelegramIsPlausible) {
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(test::read_telegram_payload("lms111_cola_a_scan.txt"), d).ok());
  const ScanPlausibility p = check_scan_plausibility(d);
  EXPECT_TRUE(p) << p.detail;
  EXPECT_TRUE(check_scan_plausibility(lms100_scan()));
}

TEST(ScanPlausibility, ScaleOtherThanOneOrTwoIsRefused) {
  for (const float scale : {-1.0F, 0.0F, 0.5F, 1000.0F}) {
    LmdScanData d = lms100_scan();
    dist1(d).scale = scale;
    const ScanPlausibility p = check_scan_plausibility(d);
    EXPECT_EQ(p.reason, ScanImplausibility::kScale) << scale;
    EXPECT_THAT(p.detail, HasSubstr("DIST1 scale factor")) << scale;
  }
  LmdScanData lms5xx = lms100_scan();
  dist1(lms5xx).scale = 2.0F;
  EXPECT_TRUE(check_scan_plausibility(lms5xx));
}

TEST(ScanPlausibility, NonZeroOffsetIsRefused) {
  LmdScanData d = lms100_scan();
  dist1(d).offset = 1e6F;  // +1 km
  const ScanPlausibility p = check_scan_plausibility(d);
  EXPECT_EQ(p.reason, ScanImplausibility::kOffset);
  EXPECT_THAT(p.detail, HasSubstr("DIST1 offset 1000000 mm"));
  EXPECT_STREQ(implausibility_counter(p.reason), "implausible_offset");
}

TEST(ScanPlausibility, ScanFrequencyOtherThan25Or50HzIsRefused) {
  LmdScanData d = lms100_scan();
  d.scan_frequency_1e2hz = 1;  // 0.01 Hz: a 100 s period
  const ScanPlausibility p = check_scan_plausibility(d);
  EXPECT_EQ(p.reason, ScanImplausibility::kScanFrequency);
  EXPECT_THAT(p.detail, HasSubstr("period 100.000 s"));
  d.scan_frequency_1e2hz = 2500;
  EXPECT_TRUE(check_scan_plausibility(d));
}

TEST(ScanPlausibility, MoreThan1141BeamsAreRefused) {
  LmdScanData d = lms100_scan(1142);
  dist1(d).step_1e4deg = 2500;
  EXPECT_EQ(check_scan_plausibility(d).reason, ScanImplausibility::kBeamCount);
}

TEST(ScanPlausibility, BeamsOutsideThe270DegreeFieldAreRefused) {
  LmdScanData d = lms100_scan();
  dist1(d).step_1e4deg = 10000;  // 541 beams at 1 deg: 540 deg
  EXPECT_EQ(check_scan_plausibility(d).reason, ScanImplausibility::kAngles);
  LmdScanData early = lms100_scan();
  dist1(early).start_angle_1e4deg = -900000;
  EXPECT_EQ(check_scan_plausibility(early).reason, ScanImplausibility::kAngles);
}

TEST(ScanPlausibility, BeamsThatDoNotFitIntoOnePeriodAreRefused) {
  LmdScanData d = lms100_scan();
  d.measurement_frequency_1e1khz = 10;  // 1 kHz: 541 beams take 541 ms of a 20 ms period
  const ScanPlausibility p = check_scan_plausibility(d);
  EXPECT_EQ(p.reason, ScanImplausibility::kBeamTiming);
  EXPECT_THAT(p.detail, HasSubstr("longer than the 20.0 ms scan period"));
}

TEST(ScanPlausibility, ReservedCodesAreNoEchoAndCounted) {
  std::vector<unsigned> raw = {0, 1, 2, 3, 9, 15, 16, 2000};
  raw.resize(541, 2000);
  LmdScanData d;
  ASSERT_TRUE(parse_lmd_scandata(test::make_scan_telegram(raw, {}, 0), d).ok());
  EXPECT_EQ(count_reserved_distance_codes(d), 4u);
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  EXPECT_EQ(s.ranges[0], 0.0F);
  EXPECT_EQ(s.ranges[1], 0.001F);  // dazzled keeps its marker
  for (size_t i = 2; i < 6; ++i) EXPECT_EQ(s.ranges[i], 0.0F) << "code " << raw[i];
  EXPECT_FLOAT_EQ(s.ranges[6], 0.016F);  // the first valid distance
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
