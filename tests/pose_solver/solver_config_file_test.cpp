#include "pose_solver/solver_config_file.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(SolverConfigFile, DeployedFileIsValidAndComplete) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/pose_solver.json");
  const SolverServiceConfig c = parse_solver_service_config(file);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_EQ(c.solver.mode, SolverMode::kDefault);
  EXPECT_EQ(c.output_channel, "LASER_POSE");
  EXPECT_DOUBLE_EQ(c.solver.outlier_threshold, 4.0);
  // The deployed range-bias keys are the code's defaults.
  const RangeBiasConfig defaults;
  const RangeBiasConfig& b = c.solver.range_bias;
  EXPECT_EQ(b.estimate, defaults.estimate);
  EXPECT_EQ(b.prior_mean, defaults.prior_mean);
  EXPECT_EQ(b.prior_sigma, defaults.prior_sigma);
  EXPECT_EQ(b.drift, defaults.drift);
  EXPECT_EQ(b.min_reflectors, defaults.min_reflectors);
  EXPECT_EQ(b.max_scan_sigma, defaults.max_scan_sigma);
  for (const char* key :
       {"/range_bias_estimate", "/range_bias_prior_mean_m", "/range_bias_prior_sigma_m",
        "/range_bias_drift_m_per_sqrt_s", "/range_bias_min_reflectors", "/range_bias_max_scan_sigma_m"})
    EXPECT_TRUE(file.has(key)) << key;
}

TEST(SolverConfigFile, RangeBiasKeysAreReadAndANoPriorWhileEstimatingIsRefused) {
  const SolverServiceConfig c = parse_solver_service_config(
      JsonConfig(nlohmann::json::parse(R"({"range_bias_estimate": false, "range_bias_prior_sigma_m": 0.0,
                                "range_bias_prior_mean_m": 0.012, "range_bias_drift_m_per_sqrt_s": 0.001})"),
                 "s.json"));
  EXPECT_FALSE(c.solver.range_bias.estimate);
  EXPECT_EQ(c.solver.range_bias.prior_sigma, 0.0);
  EXPECT_EQ(c.solver.range_bias.prior_mean, 0.012);
  EXPECT_EQ(c.solver.range_bias.drift, 0.001);
  const auto error_of = [](const char* text) -> std::string {
    try {
      parse_solver_service_config(JsonConfig(nlohmann::json::parse(text), "s.json"));
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "no ConfigError";
  };
  EXPECT_NE(error_of(R"({"range_bias_prior_sigma_m": 0.0})").find("s.json: /range_bias_prior_sigma_m"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"range_bias_min_reflectors": 3})").find("s.json: /range_bias_min_reflectors"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"range_bias_prior_mean_m": 0.6})").find("s.json: /range_bias_prior_mean_m"),
            std::string::npos);
}

TEST(SolverConfigFile, PaperModeAndRangeErrors) {
  const SolverServiceConfig c =
      parse_solver_service_config(JsonConfig(nlohmann::json::parse(R"({"mode": "paper"})"), "s.json"));
  EXPECT_EQ(c.solver.mode, SolverMode::kPaper);
  try {
    parse_solver_service_config(JsonConfig(nlohmann::json::parse(R"({"min_reflectors_ok": 2})"), "s.json"));
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("s.json: /min_reflectors_ok"), std::string::npos) << e.what();
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
