#include "lms100_driver/driver_config_file.hpp"

#include <gtest/gtest.h>

#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

DriverServiceConfig parse(const std::string& text) {
  JsonConfig file(nlohmann::json::parse(text), "test.json");
  DriverServiceConfig c = parse_driver_config(file);
  file.reject_unknown_keys();
  return c;
}

TEST(DriverConfigFile, DefaultsAre50HzHalfDegree16BitRssi) {
  const DriverServiceConfig c = parse("{}");
  EXPECT_EQ(c.session.scan.frequency_1e2hz, 5000u);
  EXPECT_EQ(c.session.scan.resolution_1e4deg, 5000u);
  EXPECT_TRUE(c.session.output.rssi);
  EXPECT_TRUE(c.session.output.rssi_16bit);
  EXPECT_EQ(c.output_channel, "LMS100_SCAN");
}

TEST(DriverConfigFile, QuarterDegreeAt25HzAnd8BitRssi) {
  const DriverServiceConfig c = parse(R"({"frequency_hz": 25, "resolution_deg": 0.25, "rssi_bits": 8})");
  EXPECT_EQ(c.session.scan.frequency_1e2hz, 2500u);
  EXPECT_EQ(c.session.scan.resolution_1e4deg, 2500u);
  EXPECT_FALSE(c.session.output.rssi_16bit);
  EXPECT_NEAR(c.session.scan_period_s(), 0.04, 1e-12);
}

TEST(DriverConfigFile, SensorAddressPortAndProtocolAreKeys) {
  const DriverServiceConfig a = parse("{}");
  EXPECT_EQ(a.session.host, "192.168.0.1");
  EXPECT_EQ(a.session.port, 2111);
  EXPECT_EQ(a.session.dialect, ColaDialect::kColaA);
  const DriverServiceConfig b = parse(R"({"host": "10.0.0.7", "protocol": "cola_b"})");
  EXPECT_EQ(b.session.host, "10.0.0.7");
  EXPECT_EQ(b.session.port, 2112);  // CoLa-B's port by convention
  EXPECT_EQ(b.session.dialect, ColaDialect::kColaB);
  EXPECT_EQ(parse(R"({"protocol": "cola_b", "port": 2111})").session.port, 2111);
}

TEST(DriverConfigFile, DeviceProfileSetsLimitsAndDefaults) {
  const DriverServiceConfig lms1xx = parse("{}");
  EXPECT_EQ(lms1xx.session.device.name, "lms1xx");
  EXPECT_TRUE(lms1xx.session.set_scan_config);
  const DriverServiceConfig lms5xx = parse(R"({"device": "lms5xx"})");
  EXPECT_DOUBLE_EQ(lms5xx.session.device.range_max_m, 80.0);
  EXPECT_EQ(lms5xx.session.scan.frequency_1e2hz, 2500u);
  EXPECT_FALSE(lms5xx.session.set_scan_config);  // the LMS1xx's mLMPsetscancfg does not fit it
  EXPECT_FALSE(lms5xx.session.output.rssi_16bit);
  const DriverServiceConfig tim = parse(R"({"device": "tim5xx_7xx"})");
  EXPECT_EQ(tim.session.scan.frequency_1e2hz, 1500u);
  EXPECT_NEAR(tim.session.scan_period_s(), 1.0 / 15.0, 1e-12);
}

TEST(DriverConfigFile, BadValuesNameTheKey) {
  const auto message = [](const std::string& text) {
    try {
      parse(text);
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(R"({"frequency_hz": 30})").find("/frequency_hz"), std::string::npos);
  EXPECT_NE(message(R"({"resolution_deg": 0.25})").find("/resolution_deg"), std::string::npos);
  EXPECT_NE(message(R"({"rssi_bits": 12})").find("/rssi_bits"), std::string::npos);
  EXPECT_NE(message(R"({"reply_timeout_s": -1})").find("/reply_timeout_s"), std::string::npos);
  EXPECT_NE(message(R"({"rssi_bit": 8})").find("/rssi_bit"), std::string::npos);
  EXPECT_NE(message(R"({"protocol": "cola_c"})").find("/protocol"), std::string::npos);
  EXPECT_NE(message(R"({"port": 0})").find("/port"), std::string::npos);
  EXPECT_NE(message(R"({"host": ""})").find("/host"), std::string::npos);
  EXPECT_NE(message(R"({"device": "lms100"})").find("/device"), std::string::npos);
  EXPECT_NE(message(R"({"device": "lms100"})").find("tim5xx_7xx"), std::string::npos);
  EXPECT_NE(message(R"({"device": "lms5xx", "set_scan_config": true})").find("/set_scan_config"),
            std::string::npos);
  EXPECT_NE(message(R"({"device": "tim5xx_7xx", "frequency_hz": 50})").find("/frequency_hz"),
            std::string::npos);
}

TEST(DriverConfigFile, DeployedFileLoads) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/lms100_driver.json");
  const DriverServiceConfig c = parse_driver_config(file);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_EQ(c.session.scan.frequency_1e2hz, 5000u);
  EXPECT_EQ(c.session.stamping.settle_reads, Lms100SessionConfig{}.stamping.settle_reads);
}

TEST(DriverConfigFile, ClockSettleReadsIsReadAndRangeChecked) {
  EXPECT_EQ(parse("{}").session.stamping.settle_reads, 5u);
  EXPECT_EQ(parse(R"({"clock_settle_reads": 10})").session.stamping.settle_reads, 10u);
  try {
    parse(R"({"clock_settle_reads": 0})");
    ADD_FAILURE() << "0 accepted";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/clock_settle_reads"), std::string::npos);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
