#include "common/json_config.hpp"
#include "pose_fusion/fusion_config_file.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace {

TEST(FusionConfigFile, DeployedFileLoads) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/pose_fusion.json");
  const FusionServiceConfig c = parse_fusion_service_config(file);
  file.reject_unknown_keys();
  EXPECT_DOUBLE_EQ(c.fusion.gate_chi2, 16.27);
  EXPECT_DOUBLE_EQ(c.fusion.lost_after, 5.0);
  EXPECT_EQ(c.fix_channel, "LASER_POSE");
}

TEST(FusionConfigFile, LostBeforeDegradedIsRefused) {
  const JsonConfig file(nlohmann::json{{"degraded_after_s", 2.0}, {"lost_after_s", 1.0}}, "pose_fusion.json");
  EXPECT_THROW(parse_fusion_service_config(file), ConfigError);
}

}  // namespace
}  // namespace refloc
