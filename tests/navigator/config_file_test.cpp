#include "common/json_config.hpp"
#include "navigator/navigator_config_file.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace {

TEST(NavigatorConfigFile, DeployedFileLoadsWithTheLibraryDefaults) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/navigator.json");
  const NavigatorServiceConfig c = parse_navigator_service_config(file);
  file.reject_unknown_keys();
  const NavigatorConfig defaults;
  EXPECT_DOUBLE_EQ(c.navigator.translation.max_speed, defaults.translation.max_speed);
  EXPECT_DOUBLE_EQ(c.navigator.translation.max_accel, defaults.translation.max_accel);
  EXPECT_NEAR(c.navigator.rotation.creep_distance, defaults.rotation.creep_distance, 1e-5);
  EXPECT_NEAR(c.navigator.default_heading_tolerance, 0.5 * M_PI / 180.0, 1e-12);
  EXPECT_DOUBLE_EQ(c.navigator.pose_timeout, 0.2);
  EXPECT_DOUBLE_EQ(c.control_rate, 50.0);
}

TEST(NavigatorConfigFile, EmptyChannelIsRefused) {
  const JsonConfig file(nlohmann::json{{"command_channel", ""}}, "navigator.json");
  EXPECT_THROW(parse_navigator_service_config(file), ConfigError);
}

}  // namespace
}  // namespace refloc
