// The header-fault commands of the emulator: each sets one falsified field, "header ok"
// restores all of them, malformed values change nothing.

#include "lms100_emulator/fault_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

TEST(FaultScanHeaderCommands, EachCommandSetsItsField) {
  FaultInjector faults;
  std::string message;
  ASSERT_TRUE(apply_fault_command("scale -1", faults, message)) << message;
  ASSERT_TRUE(apply_fault_command("offset 1000000", faults, message)) << message;
  ASSERT_TRUE(apply_fault_command("scan-frequency 1", faults, message)) << message;
  ASSERT_TRUE(apply_fault_command("beam-rate 10", faults, message)) << message;
  ASSERT_TRUE(apply_fault_command("codes on", faults, message)) << message;
  const FaultSettings s = faults.settings();
  EXPECT_EQ(s.dist_scale, -1.0F);
  EXPECT_EQ(s.dist_offset_mm, 1e6F);
  EXPECT_EQ(s.scan_frequency_1e2hz, 1u);
  EXPECT_EQ(s.measurement_frequency_1e1khz, 10u);
  EXPECT_TRUE(s.reserved_distance_codes);
  EXPECT_THAT(message, HasSubstr("header: scale -1"));
}

TEST(FaultScanHeaderCommands, HeaderOkRestoresTheHonestHeader) {
  FaultInjector faults;
  std::string message;
  ASSERT_TRUE(apply_fault_command("scale 0", faults, message));
  ASSERT_TRUE(apply_fault_command("codes on", faults, message));
  ASSERT_TRUE(apply_fault_command("header ok", faults, message));
  EXPECT_FALSE(faults.settings().corrupts_scan_header());
  EXPECT_THAT(message, ::testing::Not(HasSubstr("header:")));
}

TEST(FaultScanHeaderCommands, MalformedValuesAreRefused) {
  FaultInjector faults;
  std::string message;
  EXPECT_FALSE(apply_fault_command("scale nan", faults, message));
  EXPECT_FALSE(apply_fault_command("scale 1x", faults, message));
  EXPECT_FALSE(apply_fault_command("scan-frequency -5", faults, message));
  EXPECT_FALSE(apply_fault_command("header bad", faults, message));
  EXPECT_FALSE(faults.settings().corrupts_scan_header());
}

TEST(FaultScanHeaderCommands, CorruptionRewritesOnlyTheNamedTokens) {
  FaultSettings s;
  std::string payload =
      "sSN LMDscandata 1 1 8D4C04 0 0 1 1 0 0 0 0 7 0 0 1388 168 0 1 DIST1 3F800000 00000000 "
      "FFF92230 1388 3 10 20 30 0";
  const std::string honest = payload;
  corrupt_scan_header(s, payload);
  EXPECT_EQ(payload, honest);
  s.dist_scale = 2.0F;
  s.scan_frequency_1e2hz = 1;
  corrupt_scan_header(s, payload);
  EXPECT_THAT(payload, HasSubstr(" 0 1 168 0 1 DIST1 40000000 00000000 FFF92230 1388 3 10 20 30 0"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
