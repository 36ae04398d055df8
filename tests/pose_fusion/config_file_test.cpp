#include "common/json_config.hpp"
#include "pose_fusion/fusion_config_file.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(FusionConfigFile, DeployedFileEqualsTheCodeDefaults) {
  const FusionServiceConfig c =
      load_fusion_service_config(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/pose_fusion.json");
  const FusionServiceConfig d;
  EXPECT_EQ(c.fusion.history, d.fusion.history);
  EXPECT_EQ(c.fusion.max_fix_lead, d.fusion.max_fix_lead);
  EXPECT_EQ(c.fusion.max_deferred_fixes, d.fusion.max_deferred_fixes);
  EXPECT_EQ(c.fusion.gate_chi2, d.fusion.gate_chi2);
  EXPECT_EQ(c.fusion.degraded_after, d.fusion.degraded_after);
  EXPECT_EQ(c.fusion.lost_after, d.fusion.lost_after);
  EXPECT_EQ(c.fusion.max_consecutive_rejections, d.fusion.max_consecutive_rejections);
  EXPECT_EQ(c.continuity.max_gap, d.continuity.max_gap);
  EXPECT_EQ(c.continuity.max_speed, d.continuity.max_speed);
  EXPECT_EQ(c.continuity.max_yaw_rate, d.continuity.max_yaw_rate);
  EXPECT_EQ(c.continuity.distance_slack, d.continuity.distance_slack);
  EXPECT_EQ(c.odometry_timeout, d.odometry_timeout);
  EXPECT_EQ(c.odometry_channel, d.odometry_channel);
  EXPECT_EQ(c.fix_channel, d.fix_channel);
  EXPECT_EQ(c.output_channel, d.output_channel);
  EXPECT_DOUBLE_EQ(c.fusion.gate_chi2, 16.27);
  EXPECT_DOUBLE_EQ(c.fusion.lost_after, 5.0);
}

TEST(FusionConfigFile, LostBeforeDegradedIsRefused) {
  const JsonConfig file(nlohmann::json{{"fusion", {{"degraded_after_s", 2.0}, {"lost_after_s", 1.0}}}},
                        "pose_fusion.json");
  try {
    parse_fusion_service_config(file);
    FAIL() << "accepted lost_after_s < degraded_after_s";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("pose_fusion.json: /fusion/lost_after_s:"), std::string::npos)
        << e.what();
  }
}

TEST(FusionConfigFile, OdometryNoiseIsTheRobotsNotTheServices) {
  // Configured once, in robot.json: here (the old place) it is an unknown key.
  const JsonConfig file(nlohmann::json{{"odometry_noise", {{"translation_variance_m2_per_m", 1e-4}}}},
                        "pose_fusion.json");
  parse_fusion_service_config(file);
  EXPECT_THROW(file.reject_unknown_keys(), ConfigError);
}

TEST(FusionConfigFile, FlatKeysOfTheOldLayoutAreRejected) {
  const JsonConfig file(nlohmann::json{{"gate_chi2", 10.0}}, "pose_fusion.json");
  parse_fusion_service_config(file);
  EXPECT_THROW(file.reject_unknown_keys(), ConfigError);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
