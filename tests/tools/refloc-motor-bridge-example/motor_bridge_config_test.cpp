#include "motor_bridge_config.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(MotorBridgeConfigFile, AnEmptyFileGivesTheDefaults) {
  const JsonConfig file(nlohmann::json::object(), "bridge.json");
  const MotorBridgeConfig c = parse_motor_bridge_config(file);
  EXPECT_EQ(c.command_timeout_s, 0.2);
  EXPECT_EQ(c.encoder_rate_hz, 100.0);
}

TEST(MotorBridgeConfigFile, AnOutOfRangeTimeoutNamesFileAndKey) {
  const JsonConfig file(nlohmann::json{{"command_timeout_s", 5.0}}, "bridge.json");
  try {
    parse_motor_bridge_config(file);
    FAIL() << "accepted a 5 s command timeout";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("bridge.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("/command_timeout_s"), std::string::npos) << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
