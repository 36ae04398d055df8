// web_console's config file: defaults, the shipped file, refusals naming the key.

#include "web_console/console_config.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

WebConsoleConfig parse(const std::string& text) {
  const JsonConfig config = JsonConfig::parse_text(text, "web_console.json");
  WebConsoleConfig c = parse_web_console_config(config, "/cfg");
  config.reject_unknown_keys();
  return c;
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(WebConsoleConfig, TheShippedFileHoldsTheBuiltInDefaults) {
  const WebConsoleConfig shipped =
      load_web_console_config(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/web_console.json", "");
  const WebConsoleConfig defaults = parse("{}");
  EXPECT_EQ(shipped.server.listen_address, "127.0.0.1");
  EXPECT_EQ(shipped.server.port, defaults.server.port);
  EXPECT_EQ(shipped.server.max_clients, defaults.server.max_clients);
  EXPECT_EQ(shipped.server.client_queue_frames, defaults.server.client_queue_frames);
  EXPECT_EQ(shipped.model.scan_rate_hz, 10.0);
  EXPECT_FALSE(shipped.control.enabled);
  EXPECT_EQ(defaults.map_file, "/cfg/map_demo.json");
}

TEST(WebConsoleConfig, ControlWithoutATokenIsRefusedNamingTheKey) {
  EXPECT_NE(error_of(R"({"control": {"enabled": true}})").find("web_console.json: /control/token"),
            std::string::npos);
  EXPECT_EQ(parse(R"({"control": {"enabled": true, "token": "12345678"}})").control.token, "12345678");
}

TEST(WebConsoleConfig, BadValuesAreRefusedNamingTheKey) {
  EXPECT_NE(error_of(R"({"server": {"port": 0}})").find("/server/port"), std::string::npos);
  EXPECT_NE(error_of(R"({"server": {"allowed_origins": ["evil"]}})").find("/server/allowed_origins/0"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"model": {"scan_rate_hz": 0}})").find("/model/scan_rate_hz"), std::string::npos);
  EXPECT_NE(error_of(R"({"channels": {"pose": ""}})").find("/channels/pose"), std::string::npos);
  EXPECT_NE(error_of(R"({"sever": {}})").find("sever"), std::string::npos);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
