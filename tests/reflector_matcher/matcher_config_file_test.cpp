#include "reflector_matcher/matcher_config_file.hpp"

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

JsonConfig doc(const char* text) { return JsonConfig(nlohmann::json::parse(text), "test.json"); }

TEST(MatcherConfigFile, DeployedFileIsValidCompleteAndItsMapLoads) {
  const std::string dir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config";
  const JsonConfig file = JsonConfig::load_file(dir + "/reflector_matcher.json");
  const MatcherServiceConfig c = parse_matcher_service_config(file, dir);
  EXPECT_NO_THROW(file.reject_unknown_keys());
  EXPECT_EQ(c.matcher.mode, MatcherMode::kDefault);
  EXPECT_DOUBLE_EQ(c.prior.max_age, 0.5);
  EXPECT_GE(load_reflector_map(c.map_file).reflectors.size(), 3u);
}

TEST(MatcherConfigFile, EmptyDocumentGivesTheDefaults) {
  const MatcherServiceConfig c = parse_matcher_service_config(doc("{}"), "/base");
  const MatcherConfig defaults;
  EXPECT_EQ(c.map_file, "/base/map_demo.json");
  EXPECT_DOUBLE_EQ(c.matcher.sensor.max_range, defaults.sensor.max_range);
  EXPECT_DOUBLE_EQ(c.matcher.relocalization.max_triangle_side, 2.0 * defaults.sensor.max_range);
  EXPECT_NEAR(c.matcher.sensor.field_of_view, 270.0 * M_PI / 180.0, 1e-12);
  EXPECT_EQ(c.input_channel, "REFLECTORS");
}

TEST(MatcherConfigFile, DegreesAndRelativeMapPathAreConverted) {
  const MatcherServiceConfig c = parse_matcher_service_config(
      doc(R"({"map_file": "maps/hall.json", "mode": "paper", "paper": {"angle_tolerance_deg": 3.0},
              "relocalization": {"distinct_pose_angle_deg": 10}})"),
      "/etc/refloc");
  EXPECT_EQ(c.map_file, "/etc/refloc/maps/hall.json");
  EXPECT_EQ(c.matcher.mode, MatcherMode::kPaper);
  EXPECT_NEAR(c.matcher.paper.angle_tolerance, 3.0 * M_PI / 180.0, 1e-12);
  EXPECT_NEAR(c.matcher.relocalization.distinct_pose_angle, 10.0 * M_PI / 180.0, 1e-12);
  const MatcherServiceConfig absolute =
      parse_matcher_service_config(doc(R"({"map_file": "/m.json"})"), "/etc");
  EXPECT_EQ(absolute.map_file, "/m.json");
}

TEST(MatcherConfigFile, ErrorsNameTheKey) {
  try {
    parse_matcher_service_config(doc(R"({"relocalization": {"ambiguity_ratio": 1.5}})"), "");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("test.json: /relocalization/ambiguity_ratio"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_matcher_service_config(doc(R"({"sensor": {"min_range_m": 30}})"), ""), ConfigError);
  EXPECT_THROW(parse_matcher_service_config(doc(R"({"mode": "fast"})"), ""), ConfigError);
  try {
    parse_matcher_service_config(
        doc(R"({"relocalization": {"side_tolerance_m": 0.1, "max_side_tolerance_m": 0.05}})"), "");
    FAIL() << "no ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("/relocalization/max_side_tolerance_m"), std::string::npos)
        << e.what();
  }
  EXPECT_THROW(parse_matcher_service_config(doc(R"({"relocalization": {"side_tolerance_sigmas": -1}})"), ""),
               ConfigError);
  const JsonConfig misspelt = doc(R"({"prior_max_age": 0.5})");
  parse_matcher_service_config(misspelt, "");
  EXPECT_THROW(misspelt.reject_unknown_keys(), ConfigError);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
