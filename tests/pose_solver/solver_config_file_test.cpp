#include "pose_solver/solver_config_file.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace {

TEST(SolverConfigFile, DeployedFileIsValidAndComplete) {
  const JsonConfig file =
      JsonConfig::load_file(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/pose_solver.json");
  const SolverServiceConfig c = parse_solver_service_config(file);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_EQ(c.solver.mode, SolverMode::kDefault);
  EXPECT_EQ(c.output_channel, "LASER_POSE");
  EXPECT_DOUBLE_EQ(c.solver.outlier_threshold, 4.0);
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

}  // namespace
}  // namespace refloc
