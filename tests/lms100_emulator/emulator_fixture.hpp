#pragma once
// Starts an emulator on an ephemeral loopback port with the test pattern and a
// short spin-up, and connects a test client through the usual start-up dialogue.

#include "emulator_test_client.hpp"
#include "lms100_driver/lmd_scandata_parser.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/test_pattern_scan_source.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <thread>

namespace refloc::test {

inline Lms100EmulatorConfig make_test_emulator_config() {
  Lms100EmulatorConfig config;
  config.port = 0;
  config.device.spin_up_s = 0.05;
  return config;
}

inline std::unique_ptr<Lms100Emulator> start_emulator(const Lms100EmulatorConfig& config) {
  auto emulator = std::make_unique<Lms100Emulator>(config, make_test_pattern_scan_source());
  emulator->start();
  return emulator;
}

/// Login, RSSI 16-bit with time info, wait for STlms 7, subscribe. Returns false on any unexpected reply.
inline bool subscribe_to_stream(EmulatorTestClient& client,
                                const char* data_config = "01 00 1 1 0 00 00 0 0 0 1 +1") {
  if (client.request("sMN SetAccessMode 03 F4724744") != "sAN SetAccessMode 1") return false;
  if (client.request(std::string("sWN LMDscandatacfg ") + data_config) != "sWA LMDscandatacfg") return false;
  if (client.request("sMN Run") != "sAN Run 1") return false;
  for (int i = 0; i < 200; ++i) {
    if (client.request("sRN STlms").rfind("sRA STlms 7 ", 0) == 0) {
      return client.request("sEN LMDscandata 1") == "sEA LMDscandata 1";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return false;
}

inline LmdScanData parse_or_fail(const std::string& payload) {
  LmdScanData scan;
  const ParseResult result = parse_lmd_scandata(payload, scan);
  EXPECT_TRUE(result.ok()) << result.error;
  return scan;
}

}  // namespace refloc::test
