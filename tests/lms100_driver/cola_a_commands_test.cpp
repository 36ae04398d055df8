#include "lms100_driver/cola_a_commands.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(ColaACommands, RequestsAreTheDocumentedStrings) {
  EXPECT_EQ(request_login(), "sMN SetAccessMode 03 F4724744");
  EXPECT_EQ(request_set_scan_config(ScanConfig{}), "sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000");
  ScanConfig slow;
  slow.frequency_1e2hz = 2500;
  slow.resolution_1e4deg = 2500;
  EXPECT_EQ(request_set_scan_config(slow), "sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000");
  EXPECT_EQ(request_set_scandata_output(ScanDataOutputConfig{}),
            "sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1");
  ScanDataOutputConfig eight;
  eight.rssi_16bit = false;
  eight.time_info = false;
  EXPECT_EQ(request_set_scandata_output(eight), "sWN LMDscandatacfg 01 00 1 0 0 00 00 0 0 0 0 +1");
  EXPECT_EQ(request_read_scan_config(), "sRN LMPscancfg");
  EXPECT_EQ(request_start_measurement(), "sMN LMCstartmeas");
  EXPECT_EQ(request_stop_measurement(), "sMN LMCstopmeas");
  EXPECT_EQ(request_run(), "sMN Run");
  EXPECT_EQ(request_read_status(), "sRN STlms");
  EXPECT_EQ(request_read_device_state(), "sRN SCdevicestate");
  EXPECT_EQ(request_scandata_stream(true), "sEN LMDscandata 1");
  EXPECT_EQ(request_scandata_stream(false), "sEN LMDscandata 0");
}

TEST(ColaACommands, RepliesAreMatchedByTypeAndName) {
  EXPECT_TRUE(is_reply_to("sMN SetAccessMode 03 F4724744", "sAN SetAccessMode 1"));
  EXPECT_TRUE(is_reply_to("sMN LMCstartmeas", "sMA LMCstartmeas"));
  EXPECT_TRUE(is_reply_to("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1", "sWA LMDscandatacfg"));
  EXPECT_TRUE(is_reply_to("sRN STlms", "sRA STlms 7 0 8 00:17:28 A 01.01.1970 0 0 0"));
  EXPECT_TRUE(is_reply_to("sEN LMDscandata 1", "sEA LMDscandata 1"));
  // A duplicate reply to another command (seen on a real LMS111) is not ours.
  EXPECT_FALSE(is_reply_to("sWN LMDscandatacfg 01", "sRA LIDinputstate 0 0"));
  EXPECT_FALSE(is_reply_to("sEN LMDscandata 1", "sSN LMDscandata 1 1 8D4C04"));
  EXPECT_FALSE(is_reply_to("sRN STlms", "sRA STlmsX 7"));
}

TEST(ColaACommands, SfaCodesAreHexAndNamed) {
  uint32_t code = 0;
  ASSERT_TRUE(parse_sopas_error("sFA 11", code));
  EXPECT_EQ(code, 17u);
  EXPECT_STREQ(sopas_error_name(code), "COLA_A_INVALID_CHARACTER");
  ASSERT_TRUE(parse_sopas_error("sFA A", code));
  EXPECT_STREQ(sopas_error_name(code), "VARIABLE_WRITE_ACCESSDENIED");
  ASSERT_TRUE(parse_sopas_error("sFA 4", code));
  EXPECT_STREQ(sopas_error_name(code), "LOCALCONDITIONFAILED");
  EXPECT_STREQ(sopas_error_name(0x19), "AsyncMethodsAreSuppressed");
  EXPECT_STREQ(sopas_error_name(0x20), "ComplexArraysNotSupported");
  EXPECT_STREQ(sopas_error_name(0x1A), "unknown");
  EXPECT_FALSE(parse_sopas_error("sFA", code));
  EXPECT_FALSE(parse_sopas_error("sFA Z", code));
  EXPECT_FALSE(parse_sopas_error("sAN Run 1", code));
}

TEST(ColaACommands, ReplyChecksAcceptRealRepliesAndExplainFailures) {
  EXPECT_TRUE(check_login_reply("sAN SetAccessMode 1").ok());
  const ParseResult refused = check_login_reply("sAN SetAccessMode 0");
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error.find("refused"), std::string::npos);
  const ParseResult sfa = check_login_reply("sFA A");
  ASSERT_FALSE(sfa.ok());
  EXPECT_NE(sfa.error.find("VARIABLE_WRITE_ACCESSDENIED"), std::string::npos) << sfa.error;

  ScanConfig c25;
  c25.frequency_1e2hz = 2500;
  c25.resolution_1e4deg = 2500;
  EXPECT_TRUE(check_scan_config_reply("sAN mLMPsetscancfg 0 9C4 1 9C4 FFF92230 225510", c25).ok());
  EXPECT_FALSE(check_scan_config_reply("sAN mLMPsetscancfg 0 9C4 1 9C4 FFF92230 225510", ScanConfig{}).ok());
  const ParseResult bad_freq = check_scan_config_reply("sAN mLMPsetscancfg 1 9C4 1 9C4 FFF92230 225510", c25);
  ASSERT_FALSE(bad_freq.ok());
  EXPECT_NE(bad_freq.error.find("invalid frequency"), std::string::npos);
  EXPECT_FALSE(check_scan_config_reply("sAN mLMPsetscancfg 0 9C4", c25).ok());

  ScanConfig read;
  ASSERT_TRUE(parse_scan_config_reply("sRA LMPscancfg 1388 1 1388 FFF92230 225510", read).ok());
  EXPECT_TRUE(read == ScanConfig{});
  ASSERT_TRUE(parse_scan_config_reply("sRA LMPscancfg 9C4 1 9C4 FFFF3CB0 1C3A90", read).ok());
  EXPECT_EQ(read.start_angle_1e4deg, -50000);
  EXPECT_EQ(read.stop_angle_1e4deg, 1850000);
  EXPECT_FALSE(parse_scan_config_reply("sRA LMPscancfg 9C4 1", read).ok());
  EXPECT_FALSE(parse_scan_config_reply("sFA 3", read).ok());

  uint32_t status = 0;
  ASSERT_TRUE(parse_status_reply("sRA STlms 3 0 8 00:17:28 A 01.01.1970 0 0 0", status).ok());
  EXPECT_EQ(status, 3u);
  ASSERT_TRUE(parse_status_reply("sRA STlms 7 0 8 00:00:00 8 01.01.06 0 0 0", status).ok());
  EXPECT_EQ(status, kStatusReadyForMeasurement);
  EXPECT_FALSE(parse_status_reply("sRA STlms", status).ok());
  uint32_t state = 0;
  ASSERT_TRUE(parse_device_state_reply("sRA SCdevicestate 1", state).ok());
  EXPECT_EQ(state, kDeviceStateReady);

  EXPECT_TRUE(check_simple_reply("sAN Run 1", "sAN Run 1").ok());
  EXPECT_FALSE(check_simple_reply("sAN Run 0", "sAN Run 1").ok());
  EXPECT_FALSE(check_simple_reply("sFA 1", "sAN Run 1").ok());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
