// The emulator's implausible-header faults as the driver sees them: an encoded LMS1xx
// telegram, falsified by corrupt_scan_header, parsed by the driver and refused for the
// right reason; with the faults off the same telegram is plausible.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_driver/scan_conversion.hpp"
#include "lms100_driver/scan_plausibility.hpp"
#include "lms100_emulator/fault_injection.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

ScanPlausibility driver_verdict(const FaultSettings& faults, LmdScanData* out = nullptr) {
  const std::vector<uint16_t> dist(541, 3000);
  const std::vector<uint16_t> rssi(541, 100);
  LmdOutputOptions options;
  std::string payload;
  encode_lmd_scandata(LmdTelegramHeader{}, LmdBeamLayout{}, dist.data(), rssi.data(), dist.size(), options,
                      payload);
  corrupt_scan_header(faults, payload);
  LmdScanData d;
  const ParseResult parsed = parse_lmd_scandata(payload, d);
  EXPECT_TRUE(parsed.ok()) << parsed.error;
  if (out) *out = d;
  return check_scan_plausibility(d);
}

TEST(EmulatorHeaderFaults, HonestTelegramIsPlausible) { EXPECT_TRUE(driver_verdict(FaultSettings{})); }

TEST(EmulatorHeaderFaults, EachFalsifiedFieldIsRefusedForItsReason) {
  FaultSettings negative_scale;
  negative_scale.dist_scale = -1.0F;
  EXPECT_EQ(driver_verdict(negative_scale).reason, ScanImplausibility::kScale);
  FaultSettings zero_scale;
  zero_scale.dist_scale = 0.0F;
  EXPECT_EQ(driver_verdict(zero_scale).reason, ScanImplausibility::kScale);
  FaultSettings offset;
  offset.dist_offset_mm = 1e6F;
  EXPECT_EQ(driver_verdict(offset).reason, ScanImplausibility::kOffset);
  FaultSettings slow;
  slow.scan_frequency_1e2hz = 1;
  EXPECT_THAT(driver_verdict(slow).detail, HasSubstr("period 100.000 s"));
  FaultSettings slow_beams;
  slow_beams.measurement_frequency_1e1khz = 10;
  EXPECT_EQ(driver_verdict(slow_beams).reason, ScanImplausibility::kBeamTiming);
}

TEST(EmulatorHeaderFaults, ReservedCodesArriveAndBecomeNoEcho) {
  FaultSettings codes;
  codes.reserved_distance_codes = true;
  LmdScanData d;
  EXPECT_TRUE(driver_verdict(codes, &d)) << "codes alone do not make a header implausible";
  EXPECT_EQ(count_reserved_distance_codes(d), 14u);
  LaserScan s;
  ASSERT_TRUE(to_laser_scan(d, s).ok());
  for (size_t i = 0; i < 14; ++i) EXPECT_EQ(s.ranges[i], 0.0F) << i;
  EXPECT_FLOAT_EQ(s.ranges[14], 3.0F);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
