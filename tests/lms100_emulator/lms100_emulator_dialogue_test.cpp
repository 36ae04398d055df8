// The emulator over real loopback TCP: the command dialogue byte for byte, polls,
// client replacement and garbage.

#include "emulator_fixture.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

namespace refloc::test {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(Lms100EmulatorDialogue, AnswersTheDriverStartUpSequenceByteForByte) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  ASSERT_TRUE(client.connected());
  EXPECT_EQ(client.request("sEN LMDscandata 0"), "sEA LMDscandata 0");
  EXPECT_EQ(client.request("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  EXPECT_EQ(client.request("sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000"),
            "sAN mLMPsetscancfg 0 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(client.request("sRN LMPscancfg"), "sRA LMPscancfg 1388 1 1388 FFF92230 225510");
  EXPECT_EQ(client.request("sRN LMPoutputRange"), "sRA LMPoutputRange 1 1388 FFF92230 225510");
  EXPECT_EQ(client.request("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1"), "sWA LMDscandatacfg");
  EXPECT_EQ(client.request("sMN LMCstartmeas"), "sAN LMCstartmeas 0");
  EXPECT_EQ(client.request("sMN Run"), "sAN Run 1");
  EXPECT_EQ(client.request("sRN DeviceIdent"), "sRA DeviceIdent 10 LMS10x_FieldEval 10 V1.36-21.10.2010");
  EXPECT_EQ(client.request("sEN LMDscandata 1"), "sEA LMDscandata 1");
  EXPECT_EQ(client.request("sEN LMDscandata 0"), "sEA LMDscandata 0");
}

TEST(Lms100EmulatorDialogue, WrongPasswordIsRefusedAndWritesStayDenied) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  EXPECT_EQ(client.request("sMN SetAccessMode 03 DEADBEEF"), "sAN SetAccessMode 0");
  EXPECT_EQ(client.request("sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1"), "sFA A");
  EXPECT_EQ(client.request("sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000"), "sFA 1");
  EXPECT_EQ(client.request("sMN NoSuchMethod"), "sFA 2");
  EXPECT_EQ(client.request("sRN NoSuchVariable"), "sFA 3");
  EXPECT_EQ(client.request("sQQ LMPscancfg"), "sFA C");
}

TEST(Lms100EmulatorDialogue, StlmsProgressesFromIdleToReadyOverTheSpinUp) {
  Lms100EmulatorConfig config = make_test_emulator_config();
  config.device.spin_up_s = 0.3;
  config.device.measuring_at_power_up = false;
  auto emulator = start_emulator(config);
  EmulatorTestClient client(emulator->port());
  EXPECT_EQ(client.request("sRN STlms").substr(0, 12), "sRA STlms 3 ");
  client.request("sMN SetAccessMode 03 F4724744");
  const auto start = std::chrono::steady_clock::now();
  ASSERT_EQ(client.request("sMN LMCstartmeas"), "sAN LMCstartmeas 0");
  std::vector<int> seen;
  while (std::chrono::steady_clock::now() - start < std::chrono::milliseconds(600)) {
    const std::string reply = client.request("sRN STlms");
    ASSERT_GE(reply.size(), 11u);
    const int status = reply[10] - '0';
    if (seen.empty() || seen.back() != status) seen.push_back(status);
    if (status == 7) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  EXPECT_EQ(seen, (std::vector<int>{3, 4, 5, 7}));
  const double ready_after_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GT(ready_after_s, 0.29);
  EXPECT_LT(ready_after_s, 0.45);
}

TEST(Lms100EmulatorDialogue, PollReturnsTheLastScanAsSra) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient client(emulator->port());
  std::this_thread::sleep_for(std::chrono::milliseconds(150));
  const std::string reply = client.request("sRN LMDscandata");
  ASSERT_EQ(reply.rfind("sRA LMDscandata 1 1 8D4C04 0 0 ", 0), 0u) << reply.substr(0, 60);
  const LmdScanData scan = parse_or_fail(reply);
  EXPECT_FALSE(scan.is_stream_event);
  ASSERT_EQ(scan.channels16.size(), 2u);  // power-up data config: RSSI on, 16 bit
  ASSERT_EQ(scan.channels16[0].values.size(), 541u);
  EXPECT_EQ(scan.channels16[0].values[270], test_pattern_range_mm(0.0));
}

TEST(Lms100EmulatorDialogue, ANewClientReplacesTheOldOne) {
  auto emulator = start_emulator(make_test_emulator_config());
  EmulatorTestClient first(emulator->port());
  ASSERT_EQ(first.request("sMN SetAccessMode 03 F4724744"), "sAN SetAccessMode 1");
  EmulatorTestClient second(emulator->port());
  EXPECT_TRUE(first.wait_for_close(1000));
  // The login ended with the old connection.
  EXPECT_EQ(second.request("sMN LMCstopmeas"), "sFA 1");
  EXPECT_EQ(emulator->stats().clients_accepted, 2u);
}

TEST(Lms100EmulatorDialogue, SurvivesGarbageAndAbruptDisconnects) {
  auto emulator = start_emulator(make_test_emulator_config());
  {
    EmulatorTestClient client(emulator->port());
    std::string garbage;
    for (int i = 0; i < 5000; ++i) garbage.push_back(static_cast<char>((i * 7919) & 0xFF));
    client.send_raw(garbage);
    client.send_raw("\x02sRN STlms");  // left open: the next STX restarts the frame
    // Frames cut out of the garbage get error replies (sFA ...); the real request still gets its answer.
    client.send_request("sRN SCdevicestate");
    std::string reply;
    int error_replies = 0;
    while (!(reply = client.next_reply(1000)).empty() && reply.rfind("sRA SCdevicestate ", 0) != 0) {
      EXPECT_EQ(reply.rfind("sFA ", 0), 0u) << reply;
      ++error_replies;
    }
    EXPECT_EQ(reply.rfind("sRA SCdevicestate ", 0), 0u);
    EXPECT_GT(error_replies, 0);
    ASSERT_TRUE(subscribe_to_stream(client));
  }  // closed in the middle of the stream
  for (int i = 0; i < 3; ++i) {
    EmulatorTestClient client(emulator->port());
    EXPECT_EQ(client.request("sRN LMPscancfg"), "sRA LMPscancfg 1388 1 1388 FFF92230 225510");
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc::test
