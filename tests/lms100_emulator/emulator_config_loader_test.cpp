#include "lms100_emulator/emulator_config_loader.hpp"

#include "common/json_config.hpp"
#include "lms100_emulator/fault_command.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

JsonConfig doc(const char* text) { return JsonConfig(nlohmann::json::parse(text), "test.json"); }

TEST(EmulatorConfigLoader, EmptyDocumentGivesTheDefaults) {
  const Lms100EmulatorConfig c = parse_emulator_config(doc("{}"));
  EXPECT_EQ(c.bind_address, "127.0.0.1");
  EXPECT_EQ(c.port, 2111);
  EXPECT_EQ(c.device.scan_frequency_1e2hz, 5000u);
  EXPECT_EQ(c.device.angular_resolution_1e4deg, 5000u);
  EXPECT_DOUBLE_EQ(c.device.spin_up_s, 0.2);
  EXPECT_EQ(c.faults.split_mode, WriteSplitMode::none);
}

TEST(EmulatorConfigLoader, ReadsEveryGroup) {
  const JsonConfig file = doc(R"({"port": 0, "scan_frequency_hz": 25, "angular_resolution_deg": 0.25,
      "spin_up_s": 30, "serial_number": 18090362, "power_up_clock_us": 4294000000,
      "first_telegram_counter": 65530, "startup_status_scans": 7,
      "faults": {"split_mode": "random", "split_pieces": 5, "merge_scan_telegrams": 2,
                 "junk_bytes_between_telegrams": 9, "refuse_readiness": true}})");
  const Lms100EmulatorConfig c = parse_emulator_config(file);
  file.reject_unknown_keys();
  EXPECT_EQ(c.port, 0);
  EXPECT_EQ(c.device.scan_frequency_1e2hz, 2500u);
  EXPECT_EQ(c.device.angular_resolution_1e4deg, 2500u);
  EXPECT_DOUBLE_EQ(c.device.spin_up_s, 30.0);
  EXPECT_EQ(c.device.serial_number, 18090362u);
  EXPECT_EQ(c.power_up_clock_us, 4294000000u);
  EXPECT_EQ(c.first_telegram_counter, 65530);
  EXPECT_EQ(c.startup_status_scans, 7);
  EXPECT_EQ(c.faults.split_mode, WriteSplitMode::random);
  EXPECT_EQ(c.faults.split_pieces, 5);
  EXPECT_EQ(c.faults.merge_scan_telegrams, 2);
  EXPECT_EQ(c.faults.junk_bytes_between_telegrams, 9);
  EXPECT_TRUE(c.faults.refuse_readiness);
}

TEST(EmulatorConfigLoader, RejectsWhatAnLms100CannotDoNamingTheKey) {
  try {
    parse_emulator_config(doc(R"({"scan_frequency_hz": 50, "angular_resolution_deg": 0.25})"));
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: /angular_resolution_deg"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_emulator_config(doc(R"({"scan_frequency_hz": 40})")), ConfigError);
  EXPECT_THROW(parse_emulator_config(doc(R"({"port": 70000})")), ConfigError);
  EXPECT_THROW(parse_emulator_config(doc(R"({"faults": {"split_mode": "sideways"}})")), ConfigError);
  const JsonConfig misspelt = doc(R"({"prot": 2111})");
  parse_emulator_config(misspelt);
  EXPECT_THROW(misspelt.reject_unknown_keys(), ConfigError);
}

TEST(FaultCommand, ChangesStandingSettingsAndQueuesOneShots) {
  FaultInjector faults;
  std::string message;
  EXPECT_TRUE(apply_fault_command("split boundaries", faults, message));
  EXPECT_EQ(faults.settings().split_mode, WriteSplitMode::boundaries);
  EXPECT_TRUE(apply_fault_command("merge 4", faults, message));
  EXPECT_EQ(faults.settings().merge_scan_telegrams, 4);
  EXPECT_TRUE(apply_fault_command("ready off", faults, message));
  EXPECT_TRUE(faults.settings().refuse_readiness);
  EXPECT_EQ(message, "ok: split boundaries, merge 4, junk 0, duplicate off, ready off");
  EXPECT_TRUE(apply_fault_command("drop 2", faults, message));
  EXPECT_TRUE(faults.take_drop());
  EXPECT_TRUE(faults.take_drop());
  EXPECT_FALSE(faults.take_drop());
  EXPECT_TRUE(apply_fault_command("stall 250", faults, message));
  EXPECT_EQ(faults.take_stall_ms(), 250);
  EXPECT_TRUE(apply_fault_command("close", faults, message));
  EXPECT_TRUE(faults.take_close_now());
}

TEST(FaultCommand, RefusesMalformedLinesWithoutChangingAnything) {
  FaultInjector faults;
  std::string message;
  EXPECT_FALSE(apply_fault_command("drop", faults, message));
  EXPECT_FALSE(apply_fault_command("drop 3 extra", faults, message));
  EXPECT_FALSE(apply_fault_command("drop -1", faults, message));
  EXPECT_FALSE(apply_fault_command("merge 0", faults, message));
  EXPECT_FALSE(apply_fault_command("split sideways", faults, message));
  EXPECT_FALSE(apply_fault_command("explode", faults, message));
  EXPECT_FALSE(faults.take_drop());
  EXPECT_EQ(faults.settings().merge_scan_telegrams, 1);
  EXPECT_NE(message.find("unknown or malformed command 'explode'"), std::string::npos);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
