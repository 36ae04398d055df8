#include "lms100_emulator/lms100_device.hpp"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

class Lms100DeviceTest : public ::testing::Test {
 protected:
  std::string ask(const std::string& request, uint64_t now_us = 1000000) {
    std::string reply;
    last_action_ = device_.handle_request(request, now_us, reply);
    return reply;
  }
  void login() { ASSERT_EQ(ask("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1"); }

  Lms100DeviceConfig config_;
  Lms100Device device_{config_};
  Lms100Device::Action last_action_ = Lms100Device::Action::reply;
};

TEST_F(Lms100DeviceTest, LoginAcceptsTheThreeKnownLevelHashesAndRefusesAWrongOne) {
  EXPECT_EQ(ask("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  EXPECT_EQ(device_.login_level(), 3);
  EXPECT_EQ(ask("sMN SetAccessMode 3 F4724744"), "sAN SetAccessMode 1");
  EXPECT_EQ(ask("sMN SetAccessMode 02 B21ACE26"), "sAN SetAccessMode 1");
  EXPECT_EQ(ask("sMN SetAccessMode 04 81BE23AA"), "sAN SetAccessMode 1");
  EXPECT_EQ(device_.login_level(), 4);
  EXPECT_EQ(ask("sMN SetAccessMode 03 12345678"), "sAN SetAccessMode 0");
  EXPECT_EQ(ask("sMN SetAccessMode 03"), "sFA 8");
}

TEST_F(Lms100DeviceTest, RunAnswersOneAndLogsOut) {
  login();
  EXPECT_EQ(ask("sMN Run"), "sAN Run 1");
  EXPECT_EQ(device_.login_level(), 0);
  EXPECT_EQ(ask("sMN LMCstopmeas"), "sFA 1");
}

TEST_F(Lms100DeviceTest, ScanConfigNeedsLoginAndEchoesTheConfigurationInForce) {
  EXPECT_EQ(ask("sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000"), "sFA 1");
  login();
  EXPECT_EQ(ask("sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000"),
            "sAN mLMPsetscancfg 0 9C4 1 9C4 FFF92230 225510");
  EXPECT_EQ(ask("sRN LMPscancfg"), "sRA LMPscancfg 9C4 1 9C4 FFF92230 225510");
  EXPECT_EQ(device_.full_scan_beams(), 1081);
  // Hex arguments are accepted as well as signed decimal.
  EXPECT_EQ(ask("sMN mLMPsetscancfg 1388 1 1388 FFF92230 225510"),
            "sAN mLMPsetscancfg 0 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(device_.full_scan_beams(), 541);
}

TEST_F(Lms100DeviceTest, ScanConfigRejectsWhatAnLms1xxCannotDo) {
  login();
  // 50 Hz at 0.25 deg: invalid resolution for that frequency.
  EXPECT_EQ(ask("sMN mLMPsetscancfg +5000 +1 +2500 -450000 +2250000"),
            "sAN mLMPsetscancfg 2 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +3000 +1 +5000 -450000 +2250000"),
            "sAN mLMPsetscancfg 1 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +3000 +1 +1000 -450000 +2250000"),
            "sAN mLMPsetscancfg 3 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +5000 +1 +5000 -460000 +2250000"),
            "sAN mLMPsetscancfg 4 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +5000 +1 +5000 -450000"), "sFA 8");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000 +1"), "sFA 7");
  EXPECT_EQ(ask("sMN mLMPsetscancfg +5000 +1 +5000 -450000 xyz"), "sFA 5");
  // 25 Hz at 0.5 deg is allowed (clearpath PR #39).
  EXPECT_EQ(ask("sMN mLMPsetscancfg +2500 +1 +5000 -450000 +2250000"),
            "sAN mLMPsetscancfg 0 9C4 1 1388 FFF92230 225510");
}

TEST_F(Lms100DeviceTest, OutputRangeReportsHalfDegreeEvenAtQuarterDegreeLikeARealLms100) {
  login();
  ask("sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000");
  EXPECT_EQ(ask("sRN LMPoutputRange"), "sRA LMPoutputRange 1 1388 FFF92230 225510");
}

TEST_F(Lms100DeviceTest, OutputRangeWriteLimitsTheOutputBeams) {
  EXPECT_EQ(ask("sWN LMPoutputRange 1 1388 0 DBBA0"), "sFA A");
  login();
  EXPECT_EQ(ask("sWN LMPoutputRange 1 1388 0 DBBA0"), "sWA LMPoutputRange");  // 0 .. 90 deg
  EXPECT_EQ(ask("sRN LMPoutputRange"), "sRA LMPoutputRange 1 1388 0 DBBA0");
  const OutputBeams beams = device_.output_beams();
  EXPECT_EQ(beams.first_index, 90);
  EXPECT_EQ(beams.count, 181);
  EXPECT_EQ(beams.start_angle_1e4deg, 0);
}

TEST_F(Lms100DeviceTest, DataConfigParsesRssiResolutionAndTimeInfoFlags) {
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1"), "sFA A");
  login();
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 1 0 0 00 00 0 1 0 1 +2"), "sWA LMDscandatacfg");
  EXPECT_TRUE(device_.data_config().rssi_enabled);
  EXPECT_FALSE(device_.data_config().rssi_16bit);
  EXPECT_TRUE(device_.data_config().device_name);
  EXPECT_TRUE(device_.data_config().time_info);
  EXPECT_EQ(device_.data_config().output_interval, 2u);
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 0 1 0 00 00 0 0 0 0 +1"), "sWA LMDscandatacfg");
  EXPECT_FALSE(device_.data_config().rssi_enabled);
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0"), "sFA 8");
  EXPECT_EQ(ask("sWN LMDscandatacfg 01 00 2 1 0 00 00 0 0 0 0 +1"), "sFA 5");
}

TEST_F(Lms100DeviceTest, MeasurementStartAndStopAnswerZeroAndDriveStlms) {
  // Power-up starts the motor; with a 0.2 s spin-up the device is ready after 0.2 s.
  EXPECT_EQ(ask("sRN STlms", 10000), "sRA STlms 3 0 8 00:00:00 A 01.01.1970 0 0 0");
  EXPECT_EQ(ask("sRN SCdevicestate", 10000), "sRA SCdevicestate 0");
  EXPECT_EQ(ask("sRN STlms", 100000), "sRA STlms 4 0 8 00:00:00 A 01.01.1970 0 0 0");
  EXPECT_EQ(ask("sRN STlms", 190000), "sRA STlms 5 0 8 00:00:00 A 01.01.1970 0 0 0");
  EXPECT_EQ(ask("sRN STlms", 3723000000ULL), "sRA STlms 7 0 8 01:02:03 A 01.01.1970 0 0 0");
  EXPECT_EQ(ask("sRN SCdevicestate", 3723000000ULL), "sRA SCdevicestate 1");
  EXPECT_EQ(ask("sMN LMCstopmeas"), "sFA 1");
  login();
  EXPECT_EQ(ask("sMN LMCstopmeas", 4000000), "sAN LMCstopmeas 0");
  EXPECT_EQ(ask("sRN STlms", 4000000).substr(0, 11), "sRA STlms 3");
  EXPECT_EQ(ask("sMN LMCstartmeas", 5000000), "sAN LMCstartmeas 0");
  EXPECT_EQ(ask("sRN STlms", 5100000).substr(0, 11), "sRA STlms 4");
  EXPECT_EQ(ask("sRN STlms", 5200000).substr(0, 11), "sRA STlms 7");
}

TEST_F(Lms100DeviceTest, ChangingTheFrequencyRestartsTheSpinUp) {
  login();
  EXPECT_EQ(ask("sRN STlms", 1000000).substr(0, 11), "sRA STlms 7");
  ask("sMN mLMPsetscancfg +2500 +1 +2500 -450000 +2250000", 1000000);
  EXPECT_EQ(ask("sRN STlms", 1010000).substr(0, 11), "sRA STlms 3");
  EXPECT_EQ(ask("sRN STlms", 1300000).substr(0, 11), "sRA STlms 7");
}

TEST_F(Lms100DeviceTest, RefusedReadinessKeepsStlmsAtFour) {
  device_.set_refuse_readiness(true);
  EXPECT_EQ(ask("sRN STlms", 100000000).substr(0, 11), "sRA STlms 4");
  device_.set_refuse_readiness(false);
  EXPECT_EQ(ask("sRN STlms", 100000000).substr(0, 11), "sRA STlms 7");
}

TEST_F(Lms100DeviceTest, ArmedRefusalAnswersTheFirstWriteWithSfa4Once) {
  device_.arm_refuse_next_write();
  login();
  EXPECT_EQ(ask("sWN LMPoutputRange 1 1388 FFF92230 225510"), "sFA 4");
  EXPECT_EQ(ask("sWN LMPoutputRange 1 1388 FFF92230 225510"), "sWA LMPoutputRange");
}

TEST_F(Lms100DeviceTest, StreamSubscriptionEchoesTheFlag) {
  EXPECT_EQ(ask("sEN LMDscandata 1"), "sEA LMDscandata 1");
  EXPECT_TRUE(device_.stream_enabled());
  EXPECT_EQ(ask("sEN LMDscandata 0"), "sEA LMDscandata 0");
  EXPECT_FALSE(device_.stream_enabled());
  EXPECT_EQ(ask("sEN LMDscandata 2"), "sFA 5");
  EXPECT_EQ(ask("sEN LMDscandata"), "sFA 8");
  EXPECT_EQ(ask("sEN NoSuchEvent 1"), "sFA F");
  ask("sEN LMDscandata 1");
  device_.on_client_disconnected();
  EXPECT_FALSE(device_.stream_enabled());
}

TEST_F(Lms100DeviceTest, PollingAScanAsksTheCallerForTheTelegram) {
  EXPECT_EQ(ask("sRN LMDscandata"), "");
  EXPECT_EQ(last_action_, Lms100Device::Action::reply_with_scan);
}

TEST_F(Lms100DeviceTest, IdentityVariablesUseLengthPrefixedStrings) {
  EXPECT_EQ(ask("sRN DeviceIdent"), "sRA DeviceIdent 10 LMS10x_FieldEval 10 V1.36-21.10.2010");
  EXPECT_EQ(ask("sRN FirmwareVersion"), "sRA FirmwareVersion 7 V1.80.2");
  EXPECT_EQ(ask("sRN LocationName"), "sRA LocationName B not defined");
  EXPECT_EQ(ask("sRN LMDscandatacfg"), "sRA LMDscandatacfg 1 0 1 1 0 0 0 0 0 0 0 1");
}

TEST_F(Lms100DeviceTest, ErrorsUseTheSopasCodes) {
  EXPECT_EQ(ask("sMN NoSuchMethod"), "sFA 2");
  EXPECT_EQ(ask("sRN NoSuchVariable"), "sFA 3");
  EXPECT_EQ(ask("sWN NoSuchVariable 1"), "sFA 3");
  EXPECT_EQ(ask("sWN STlms 7"), "sFA A");
  EXPECT_EQ(ask("sXX LMPscancfg"), "sFA C");
  EXPECT_EQ(ask("sRN"), "sFA C");
  EXPECT_EQ(ask(""), "sFA C");
  EXPECT_EQ(ask(std::string("sMN mLMPsetscancfg \x01\x02", 21)), "sFA 11");
  EXPECT_EQ(ask("sRN STlms 1"), "sFA 7");
}

TEST(Lms100DeviceRandomRequests, EveryRequestGetsAnAnswerOrAScanAndTheDeviceStaysUsable) {
  // Requests built from real command words, numbers and junk, in random order and count.
  const std::vector<std::string> words = {"sMN",
                                          "sRN",
                                          "sWN",
                                          "sEN",
                                          "sAN",
                                          "sFA",
                                          "SetAccessMode",
                                          "mLMPsetscancfg",
                                          "LMPscancfg",
                                          "LMPoutputRange",
                                          "LMDscandatacfg",
                                          "LMDscandata",
                                          "LMCstartmeas",
                                          "LMCstopmeas",
                                          "Run",
                                          "STlms",
                                          "03",
                                          "F4724744",
                                          "+5000",
                                          "-450000",
                                          "+2500",
                                          "1388",
                                          "FFF92230",
                                          "225510",
                                          "0",
                                          "1",
                                          "2",
                                          "+1",
                                          "",
                                          "-",
                                          "+",
                                          "FFFFFFFFF",
                                          "\x01"};
  std::mt19937 rng(7);
  Lms100Device device{Lms100DeviceConfig{}};
  std::string reply;
  int scans = 0;
  for (int i = 0; i < 20000; ++i) {
    std::string request;
    const int n = std::uniform_int_distribution<int>(0, 14)(rng);
    for (int k = 0; k < n; ++k) {
      if (k > 0) request += ' ';
      request += words[std::uniform_int_distribution<size_t>(0, words.size() - 1)(rng)];
    }
    if (i % 97 == 0) request += static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
    const auto action = device.handle_request(request, static_cast<uint64_t>(i) * 1000, reply);
    if (action == Lms100Device::Action::reply_with_scan) {
      ++scans;
      continue;
    }
    ASSERT_GE(reply.size(), 5u) << "request '" << request << "'";
    const std::string type = reply.substr(0, 3);
    ASSERT_TRUE(type == "sAN" || type == "sRA" || type == "sWA" || type == "sEA" || type == "sFA")
        << "request '" << request << "' -> '" << reply << "'";
    ASSERT_GE(device.output_beams().count, 0);
    ASSERT_LE(device.output_beams().count, device.full_scan_beams());
  }
  EXPECT_GT(scans, 0);
  // Whatever happened, a fresh login and a valid configuration still work.
  device.handle_request("sMN SetAccessMode 03 F4724744", 30000000, reply);
  EXPECT_EQ(reply, "sAN SetAccessMode 1");
  device.handle_request("sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000", 30000000, reply);
  EXPECT_EQ(reply, "sAN mLMPsetscancfg 0 1388 1 1388 FFF92230 225510");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
