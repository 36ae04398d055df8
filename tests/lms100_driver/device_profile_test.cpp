// Device profiles (/device): the limits a scan is checked against and the range limits it is
// published with; a multi-layer telegram (MRS1000, layer angle != 0) is refused, not interleaved.

#include "lms100_driver/device_profile.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_plausibility.hpp"
#include "telegram_fixtures.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

LmdScanData scan_of(size_t beams, uint32_t frequency_1e2hz = 5000) {
  LmdScanData d;
  EXPECT_TRUE(
      parse_lmd_scandata(test::make_scan_telegram(std::vector<unsigned>(beams, 2000), {}, 0), d).ok());
  d.scan_frequency_1e2hz = frequency_1e2hz;
  return d;
}

const DeviceProfile& profile(const char* name) {
  const DeviceProfile* p = find_device_profile(name);
  EXPECT_NE(p, nullptr) << name;
  return *p;
}

TEST(DeviceProfile, RangeLimitsAndRssiResolutionPerDevice) {
  EXPECT_EQ(lms1xx_profile().name, "lms1xx");
  EXPECT_DOUBLE_EQ(lms1xx_profile().range_max_m, 20.0);
  EXPECT_DOUBLE_EQ(profile("lms5xx").range_max_m, 80.0);
  EXPECT_DOUBLE_EQ(profile("tim5xx_7xx").range_max_m, 25.0);
  EXPECT_EQ(lms1xx_profile().default_rssi_bits, 16);
  EXPECT_EQ(profile("lms5xx").default_rssi_bits, 8);
  EXPECT_EQ(find_device_profile("lms100"), nullptr);
  EXPECT_EQ(device_profile_names(), "lms1xx, lms5xx, tim5xx_7xx");
}

TEST(DeviceProfile, BeamCountLimitFollowsTheDevice) {
  // 2281 beams: an LMS5xx's 190 deg at 1/12 deg; more than any LMS1xx sends.
  LmdScanData wide = scan_of(2281, 2500);
  wide.channels16.at(0).start_angle_1e4deg = -50000;
  wide.channels16.at(0).step_1e4deg = 833;
  wide.measurement_frequency_1e1khz = 1000;
  const ScanPlausibility as_lms1xx = check_scan_plausibility(wide, lms1xx_profile());
  EXPECT_EQ(as_lms1xx.reason, ScanImplausibility::kBeamCount);
  EXPECT_THAT(as_lms1xx.detail, HasSubstr("expected 1..1141 for lms1xx"));
  const ScanPlausibility as_lms5xx = check_scan_plausibility(wide, profile("lms5xx"));
  EXPECT_TRUE(as_lms5xx) << as_lms5xx.detail;
}

TEST(DeviceProfile, ScanFrequencyFollowsTheDevice) {
  const LmdScanData at_50hz = scan_of(541);
  EXPECT_TRUE(check_scan_plausibility(at_50hz, lms1xx_profile()));
  const ScanPlausibility as_tim = check_scan_plausibility(at_50hz, profile("tim5xx_7xx"));
  EXPECT_EQ(as_tim.reason, ScanImplausibility::kScanFrequency);
  EXPECT_THAT(as_tim.detail, HasSubstr("expected 15 Hz for tim5xx_7xx"));
  LmdScanData at_15hz = scan_of(271, 1500);
  at_15hz.channels16.at(0).step_1e4deg = 10000;
  EXPECT_TRUE(check_scan_plausibility(at_15hz, profile("tim5xx_7xx")));
  EXPECT_EQ(check_scan_plausibility(at_15hz, lms1xx_profile()).reason, ScanImplausibility::kScanFrequency);
}

TEST(DeviceProfile, FieldOfViewFollowsTheDevice) {
  // An LMS1xx's 270 deg field reaches -45 deg; an LMS5xx's 190 deg field starts at -5 deg.
  const LmdScanData lms100 = scan_of(541);
  EXPECT_EQ(check_scan_plausibility(lms100, profile("lms5xx")).reason, ScanImplausibility::kAngles);
}

TEST(DeviceProfile, MultiLayerTelegramIsRefusedWithTheReasonWhateverTheProfile) {
  // The real MRS1000 telegram: four layers sent one after another, each with its layer angle.
  LmdScanData mrs;
  ASSERT_TRUE(parse_lmd_scandata(test::read_telegram_payload("mrs1000_cola_a.txt"), mrs).ok());
  ASSERT_NE(mrs.reserved_layer_angle, 0u);
  for (const char* name : {"lms1xx", "lms5xx", "tim5xx_7xx"}) {
    const ScanPlausibility p = check_scan_plausibility(mrs, profile(name));
    EXPECT_EQ(p.reason, ScanImplausibility::kLayerAngle) << name;
    EXPECT_THAT(p.detail, HasSubstr("multi-layer scanner"));
  }
  EXPECT_STREQ(implausibility_counter(ScanImplausibility::kLayerAngle), "multi_layer_scans");
  LmdScanData single = scan_of(541);
  single.reserved_layer_angle = 0xFF06;  // -250 (x 1/10000 deg), as an MRS1000's lower layer
  EXPECT_EQ(check_scan_plausibility(single).reason, ScanImplausibility::kLayerAngle);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
