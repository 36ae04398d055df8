// The deployed config files load, and mistakes in them are named.

#include "common/json_config.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

TEST(OdometryConfigFile, DeployedFileLoadsWithTheLibraryDefaults) {
  const JsonConfig file = JsonConfig::load_file(kConfigDir + "mecanum_odometry.json");
  const OdometryServiceConfig c = parse_odometry_service_config(file);
  file.reject_unknown_keys();
  const OdometryServiceConfig defaults;
  EXPECT_EQ(c.odometry.max_gap, defaults.odometry.max_gap);
  EXPECT_EQ(c.odometry.max_plausible_wheel_speed, defaults.odometry.max_plausible_wheel_speed);
  EXPECT_EQ(c.slip_warning, defaults.slip_warning);
  EXPECT_EQ(c.input_channel, "WHEEL_ENCODERS");
  EXPECT_EQ(c.output_channel, "ODOMETRY");
}

TEST(OdometryConfigFile, NoiseIsTheRobotsNotTheServices) {
  // The increment noise is configured once, in robot.json; here it is an unknown key.
  const JsonConfig file(nlohmann::json{{"noise", {{"translation_variance_m2_per_m", 1e-4}}}},
                        "mecanum_odometry.json");
  parse_odometry_service_config(file);
  EXPECT_THROW(file.reject_unknown_keys(), ConfigError);
}

TEST(OdometryConfigFile, OutOfRangeKeyIsNamedWithItsSection) {
  const JsonConfig file(nlohmann::json{{"odometry", {{"max_gap_s", 0.0}}}}, "mecanum_odometry.json");
  try {
    parse_odometry_service_config(file);
    FAIL() << "accepted max_gap_s = 0";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("mecanum_odometry.json: /odometry/max_gap_s:"), std::string::npos)
        << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
