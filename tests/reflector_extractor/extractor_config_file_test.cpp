#include "reflector_extractor/extractor_config_file.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(ExtractorConfigFile, DeployedFileIsValidAndEqualsTheCodeDefaults) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/reflector_extractor.json");
  const ExtractorServiceConfig c = parse_extractor_service_config(file);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  const ExtractorConfig defaults;
  EXPECT_EQ(c.extractor.mode, ExtractorConfig::Mode::kDefault);
  EXPECT_DOUBLE_EQ(c.extractor.energy_threshold_8bit, defaults.energy_threshold_8bit);
  EXPECT_DOUBLE_EQ(c.extractor.reflector_radius, 0.06);
  EXPECT_NEAR(c.extractor.clustering.lambda, defaults.clustering.lambda, 1e-12);
  EXPECT_DOUBLE_EQ(c.extractor.paper_roundness.offset, defaults.paper_roundness.offset);
  EXPECT_DOUBLE_EQ(c.extractor.paper_roundness.slope, defaults.paper_roundness.slope);
  EXPECT_EQ(c.extractor.paper_centre, defaults.paper_centre);
  EXPECT_DOUBLE_EQ(c.extractor.angle_sigma, defaults.angle_sigma);
  EXPECT_DOUBLE_EQ(c.extractor.fit.min_incidence_cos, defaults.fit.min_incidence_cos);
  EXPECT_DOUBLE_EQ(c.extractor.roundness.flat_chi2_margin, defaults.roundness.flat_chi2_margin);
  EXPECT_TRUE(c.motion_compensation);
  EXPECT_EQ(c.rssi_scale.mode, RssiScaleConfig::Mode::kAuto);
  EXPECT_DOUBLE_EQ(c.no_reflector_timeout, ExtractorServiceConfig{}.no_reflector_timeout);
  EXPECT_EQ(c.input_channel, "LMS100_SCAN");
  EXPECT_EQ(c.output_channel, "REFLECTORS");
  EXPECT_EQ(c.laser_pose_channel, "LASER_POSE");
  const FixVelocityConfig fix_defaults;
  EXPECT_EQ(c.fix_velocity.enabled, fix_defaults.enabled);
  EXPECT_DOUBLE_EQ(c.fix_velocity.window_s, fix_defaults.window_s);
  EXPECT_DOUBLE_EQ(c.fix_velocity.max_age_s, fix_defaults.max_age_s);
  EXPECT_EQ(c.fix_velocity.min_fixes, fix_defaults.min_fixes);
  EXPECT_DOUBLE_EQ(c.fix_velocity.min_span_s, fix_defaults.min_span_s);
  EXPECT_DOUBLE_EQ(c.fix_velocity.max_rms_residual_m, fix_defaults.max_rms_residual_m);
}

TEST(ExtractorConfigFile, FixVelocityKeysAreReadAndASpanLongerThanTheWindowNamesItsKey) {
  const JsonConfig file(nlohmann::json{{"laser_pose_channel", "LASER_POSE_2"},
                                       {"fix_velocity",
                                        {{"enabled", false},
                                         {"window_s", 0.5},
                                         {"max_age_s", 0.1},
                                         {"min_fixes", 8},
                                         {"min_span_s", 0.2},
                                         {"max_rms_residual_m", 0.01}}}},
                        "t");
  const ExtractorServiceConfig c = parse_extractor_service_config(file);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_EQ(c.laser_pose_channel, "LASER_POSE_2");
  EXPECT_FALSE(c.fix_velocity.enabled);
  EXPECT_DOUBLE_EQ(c.fix_velocity.window_s, 0.5);
  EXPECT_DOUBLE_EQ(c.fix_velocity.max_age_s, 0.1);
  EXPECT_EQ(c.fix_velocity.min_fixes, 8);
  EXPECT_DOUBLE_EQ(c.fix_velocity.min_span_s, 0.2);
  EXPECT_DOUBLE_EQ(c.fix_velocity.max_rms_residual_m, 0.01);
  try {
    parse_extractor_service_config(
        JsonConfig(nlohmann::json{{"fix_velocity", {{"window_s", 0.1}, {"min_span_s", 0.2}}}}, "x.json"));
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("x.json: /fix_velocity/min_span_s"), std::string::npos) << e.what();
  }
  EXPECT_THROW(
      parse_extractor_service_config(JsonConfig(nlohmann::json{{"fix_velocity", {{"min_fixes", 1}}}}, "t")),
      ConfigError);
  EXPECT_THROW(
      parse_extractor_service_config(JsonConfig(nlohmann::json{{"fix_velocity", {{"window_s", 0.0}}}}, "t")),
      ConfigError);
}

TEST(ExtractorConfigFile, PaperModeStartsFromThePaperPreset) {
  const JsonConfig file(nlohmann::json{{"mode", "paper"}, {"clustering", {{"lambda_deg", 15.0}}}}, "test");
  const ExtractorServiceConfig c = parse_extractor_service_config(file);
  EXPECT_EQ(c.extractor.mode, ExtractorConfig::Mode::kPaper);
  EXPECT_EQ(c.extractor.clustering.max_gap_beams, -1);
  EXPECT_EQ(c.extractor.min_beams, 3);
  EXPECT_NEAR(c.extractor.clustering.lambda, 15.0 * M_PI / 180.0, 1e-12);
}

TEST(ExtractorConfigFile, PaperCentreReadingIsReadAndAnUnknownOneNamesItsPointer) {
  EXPECT_EQ(parse_extractor_service_config(JsonConfig(nlohmann::json{{"mode", "paper"}}, "t"))
                .extractor.paper_centre,
            PaperCentreReading::kKnownRadius);
  const auto reading = [](const char* name) {
    return parse_extractor_service_config(
               JsonConfig(nlohmann::json{{"mode", "paper"}, {"paper", {{"centre", name}}}}, "t"))
        .extractor.paper_centre;
  };
  EXPECT_EQ(reading("kasa"), PaperCentreReading::kAlgebraicFreeRadius);
  EXPECT_EQ(reading("polar"), PaperCentreReading::kPolar);
  EXPECT_EQ(reading("known_radius"), PaperCentreReading::kKnownRadius);
  try {
    reading("median");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/paper/centre"), std::string::npos) << e.what();
  }
}

TEST(ExtractorConfigFile, OutOfRangeValueNamesItsPointer) {
  const JsonConfig file(nlohmann::json{{"default", {{"fit", {{"min_incidence_cos", 2.0}}}}}}, "x.json");
  try {
    parse_extractor_service_config(file);
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("x.json: /default/fit/min_incidence_cos"), std::string::npos)
        << e.what();
  }
}

TEST(ExtractorConfigFile, RssiScaleAndNoReflectorTimeoutAreRead) {
  const JsonConfig file(nlohmann::json{{"rssi_scale", "8bit_in_16bit"}, {"no_reflector_timeout_s", 5.0}},
                        "t");
  const ExtractorServiceConfig c = parse_extractor_service_config(file);
  EXPECT_EQ(c.rssi_scale.mode, RssiScaleConfig::Mode::k8bitIn16bit);
  EXPECT_DOUBLE_EQ(c.no_reflector_timeout, 5.0);
  EXPECT_THROW(parse_extractor_service_config(JsonConfig(nlohmann::json{{"rssi_scale", "12bit"}}, "t")),
               ConfigError);
  EXPECT_THROW(
      parse_extractor_service_config(JsonConfig(nlohmann::json{{"no_reflector_timeout_s", 0.0}}, "t")),
      ConfigError);
}

TEST(ExtractorConfigFile, UnknownModeIsRejected) {
  const JsonConfig file(nlohmann::json{{"mode", "fast"}}, "x.json");
  EXPECT_THROW(parse_extractor_service_config(file), ConfigError);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
