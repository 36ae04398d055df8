// Map format 2 (docs/map-format.md): the header, reflector type and covariance, occluders;
// every key's error names the file and the key; format-1 files refuse the new keys.

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

constexpr const char* kHeader =
    R"("format": 2, "map_id": "hall_a", "version": 3, "created": "2026-12-03T06:30:58Z", "source": "surveyed")";
constexpr const char* kThreeReflectors =
    R"({"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 5, "y": 0}, {"id": 3, "x": 0, "y": 4})";

ReflectorMap parse(const std::string& text) {
  const JsonConfig config = JsonConfig::parse_text(text, "map.json");
  ReflectorMap map = parse_reflector_map(config);
  config.reject_unknown_keys();
  return map;
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

// A v2 map with the header replaced by header and extra keys after the reflector list.
std::string v2(const std::string& header, const std::string& first_reflector_extra = "",
               const std::string& tail = "") {
  return "{" + header + R"(, "reflectors": [{"id": 1, "x": 0, "y": 0)" + first_reflector_extra +
         R"(}, {"id": 2, "x": 5, "y": 0}, {"id": 3, "x": 0, "y": 4}])" + tail + "}";
}

TEST(ReflectorMapV2, ReadsHeaderTypeCovarianceAndOccluders) {
  const ReflectorMap map =
      parse(v2(kHeader, R"(, "type": "cylinder_120", "covariance_m2": [4e-6, 1e-6, 9e-6])",
               R"(, "occluders": [{"name": "hall", "points": [[0, 0], [20, 0], [20, 12]], "closed": true},
                                  {"name": "rack", "points": [[5, 5.2], [9, 5.2]]}])"));
  EXPECT_EQ(map.info.format, 2);
  EXPECT_EQ(map.info.map_id, "hall_a");
  EXPECT_EQ(map.info.version, 3);
  EXPECT_EQ(map.info.created, "2026-12-03T06:30:58Z");
  EXPECT_EQ(map.info.source, "surveyed");
  EXPECT_EQ(map.reflectors[0].type, "cylinder_120");
  ASSERT_TRUE(map.reflectors[0].map_cov_center.has_value());
  EXPECT_DOUBLE_EQ((*map.reflectors[0].map_cov_center)(0, 1), 1e-6);
  EXPECT_DOUBLE_EQ((*map.reflectors[0].map_cov_center)(1, 0), 1e-6);
  EXPECT_DOUBLE_EQ((*map.reflectors[0].map_cov_center)(1, 1), 9e-6);
  EXPECT_FALSE(map.reflectors[1].map_cov_center.has_value());
  ASSERT_EQ(map.occluders.size(), 2u);
  EXPECT_TRUE(map.occluders[0].closed);
  EXPECT_FALSE(map.occluders[1].closed);
  EXPECT_EQ(map.occluders[1].name, "rack");
  EXPECT_DOUBLE_EQ(map.occluders[0].map_points[2].y(), 12.0);
}

TEST(ReflectorMapV2, FormatOneFileLoadsWithEmptyHeader) {
  const ReflectorMap map = parse(std::string(R"({"reflectors": [)") + kThreeReflectors + "]}");
  EXPECT_EQ(map.info.format, 1);
  EXPECT_EQ(map.info.map_id, "");
  EXPECT_EQ(map.info.version, 0);
  EXPECT_TRUE(map.occluders.empty());
}

TEST(ReflectorMapV2, FormatOneFileRefusesFormatTwoKeys) {
  const std::string hint = "a format-2 key in a format-1 map: add \"format\": 2";
  EXPECT_THAT(error_of(std::string(R"({"map_id": "a", "reflectors": [)") + kThreeReflectors + "]}"),
              HasSubstr("map.json: /map_id: " + hint));
  EXPECT_THAT(error_of(std::string(R"({"occluders": [], "reflectors": [)") + kThreeReflectors + "]}"),
              HasSubstr("map.json: /occluders: " + hint));
  EXPECT_THAT(error_of(v2(R"("format": 1)", R"(, "covariance_m2": [1, 0, 1])")),
              HasSubstr("map.json: /reflectors/0/covariance_m2: " + hint));
  EXPECT_THAT(error_of(v2(R"("format": 1)", R"(, "type": "foil")")),
              HasSubstr("map.json: /reflectors/0/type: " + hint));
}

TEST(ReflectorMapV2, UnknownFormatIsRefused) {
  EXPECT_THAT(error_of(v2(R"("format": 3)")),
              HasSubstr("map.json: /format: expected an integer in [1, 2], got 3"));
}

TEST(ReflectorMapV2, HeaderKeysAreRequiredAndChecked) {
  const std::string rest = R"(, "created": "2026-12-03T06:30:58Z", "source": "typed")";
  EXPECT_THAT(error_of(v2(R"("format": 2, "version": 1)" + rest)), HasSubstr("map.json: /map_id: missing"));
  EXPECT_THAT(
      error_of(v2(R"("format": 2, "map_id": "", "version": 1)" + rest)),
      HasSubstr("map.json: /map_id: expected a map id naming the hall or layout (1 to 200 characters"));
  EXPECT_THAT(error_of(v2(R"("format": 2, "map_id": "a")" + rest)), HasSubstr("map.json: /version: missing"));
  EXPECT_THAT(error_of(v2(R"("format": 2, "map_id": "a", "version": 0)" + rest)),
              HasSubstr("map.json: /version: expected an integer in [1, 1000000000], got 0"));
  EXPECT_THAT(error_of(v2(R"("format": 2, "map_id": "a", "version": 1, "source": "typed")")),
              HasSubstr("map.json: /created: missing"));
  EXPECT_THAT(error_of(v2(R"("format": 2, "map_id": "a", "version": 1, "created": "2026-12-03T06:30:58Z")")),
              HasSubstr("map.json: /source: missing"));
  EXPECT_THAT(error_of(v2(R"("format": 2, "map_id": "a", "version": 1, "created": "2026-12-03T06:30:58Z",
                             "source": "guessed")")),
              HasSubstr("map.json: /source: expected one of \"imported\", \"merged\", \"surveyed\", "
                        "\"typed\", \"updated\""));
}

TEST(ReflectorMapV2, CreatedMustBeIso8601Utc) {
  for (const char* bad : {"2026-12-03 06:30:58", "2026-12-03T06:30:58+01:00", "2026-13-03T06:30:58Z",
                          "2026-02-29T06:30:58Z", "2026-12-03T24:00:00Z", "yesterday"}) {
    const std::string header =
        std::string(R"("format": 2, "map_id": "a", "version": 1, "source": "typed", )") + R"("created": ")" +
        bad + "\"";
    EXPECT_THAT(error_of(v2(header)), HasSubstr("map.json: /created: expected an ISO 8601 UTC time")) << bad;
  }
  EXPECT_TRUE(is_iso8601_utc("2028-02-29T23:59:60.125Z"));
}

TEST(ReflectorMapV2, CovarianceMustBeThreeNumbersPositiveDefinite) {
  const auto with = [](const std::string& cov) {
    return error_of(v2(kHeader, R"(, "covariance_m2": )" + cov));
  };
  EXPECT_THAT(with("[1e-6, 0]"),
              HasSubstr("map.json: /reflectors/0/covariance_m2: expected [xx, xy, yy], got an "
                        "array of 2"));
  EXPECT_THAT(with("0.001"), HasSubstr("map.json: /reflectors/0/covariance_m2: expected an array"));
  EXPECT_THAT(with(R"([1e-6, "0", 1e-6])"),
              HasSubstr("map.json: /reflectors/0/covariance_m2/1: expected a number"));
  EXPECT_THAT(with("[0, 0, 1e-6]"),
              HasSubstr("map.json: /reflectors/0/covariance_m2: expected a positive definite "
                        "covariance (xx > 0, yy > 0, xy^2 < xx*yy), got [0, 0, 1e-06]"));
  EXPECT_THAT(with("[1e-6, 2e-6, 1e-6]"), HasSubstr("expected a positive definite covariance"));
  EXPECT_THAT(with("[1e-6, 1e-6, 1e-6]"), HasSubstr("expected a positive definite covariance"));
  EXPECT_THAT(with("[1e5, 0, 1]"),
              HasSubstr("map.json: /reflectors/0/covariance_m2/0: expected a finite number in "
                        "[-10000, 10000]"));
  // Variances of a nanometre squared are tiny but valid: no determinant underflow.
  EXPECT_EQ(with("[1e-300, 1e-301, 1e-300]"), "");
}

TEST(ReflectorMapV2, TypeMustBeAString) {
  EXPECT_THAT(error_of(v2(kHeader, R"(, "type": 120)")),
              HasSubstr("map.json: /reflectors/0/type: expected a string, got number 120"));
}

TEST(ReflectorMapV2, OccluderErrorsNameTheKey) {
  const auto with = [](const std::string& occluders) {
    return error_of(v2(kHeader, "", R"(, "occluders": )" + occluders));
  };
  EXPECT_THAT(with("{}"), HasSubstr("map.json: /occluders: expected an array"));
  EXPECT_THAT(with(R"([{"points": [[0, 0], [1, 0]]}])"), HasSubstr("map.json: /occluders/0/name: missing"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0]]}])"),
              HasSubstr("map.json: /occluders/0/points: expected at least 2 points, got 1"));
  EXPECT_THAT(with(R"([{"name": "w"}])"), HasSubstr("map.json: /occluders/0/points: missing"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [1, 0]], "closed": true}])"),
              HasSubstr("map.json: /occluders/0/closed: a closed polyline needs at least 3 points"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [1, 0]], "closed": "yes"}])"),
              HasSubstr("map.json: /occluders/0/closed: expected true or false"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [1, 0, 2]]}])"),
              HasSubstr("map.json: /occluders/0/points/1: expected a point [x, y], got an array of 3"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [1, 1e6]]}])"),
              HasSubstr("map.json: /occluders/0/points/1/1: expected a finite number in [-100000, 100000]"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [0, 0]]}])"),
              HasSubstr("map.json: /occluders/0/points/1: repeats the previous point"));
  EXPECT_THAT(with(R"([{"name": "w", "points": [[0, 0], [1, 0]], "height": 2}])"),
              HasSubstr("map.json: /occluders/0/height: unknown key"));
}

TEST(ReflectorMapV2, DemoV2MapIsTheDemoMapPlusTheWorldsWallsAndObstacles) {
  const std::string dir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";
  const ReflectorMap v2 = load_reflector_map(dir + "map_demo_v2.json");
  const ReflectorMap v1 = load_reflector_map(dir + "map_demo.json");
  EXPECT_EQ(v2.info.source, "typed");
  ASSERT_EQ(v2.reflectors.size(), v1.reflectors.size());
  for (size_t i = 0; i < v1.reflectors.size(); ++i) {
    EXPECT_EQ(v2.reflectors[i].id, v1.reflectors[i].id);
    EXPECT_EQ(v2.reflectors[i].map_p_center, v1.reflectors[i].map_p_center);
    EXPECT_EQ(v2.reflectors[i].radius, v1.reflectors[i].radius);
    EXPECT_FALSE(v2.reflectors[i].map_cov_center.has_value());
  }
  // The world file's surfaces the laser cannot see through; distractors are not occluders.
  const nlohmann::json world = nlohmann::json::parse(std::ifstream(dir + "world_demo.json"));
  std::vector<nlohmann::json> surfaces(world["walls"].begin(), world["walls"].end());
  surfaces.insert(surfaces.end(), world["obstacles"].begin(), world["obstacles"].end());
  ASSERT_EQ(v2.occluders.size(), surfaces.size());
  for (size_t i = 0; i < surfaces.size(); ++i) {
    EXPECT_EQ(v2.occluders[i].name, surfaces[i]["name"].get<std::string>());
    EXPECT_EQ(v2.occluders[i].closed, surfaces[i]["closed"].get<bool>());
    ASSERT_EQ(v2.occluders[i].map_points.size(), surfaces[i]["points"].size());
    for (size_t k = 0; k < v2.occluders[i].map_points.size(); ++k) {
      EXPECT_EQ(v2.occluders[i].map_points[k].x(), surfaces[i]["points"][k][0].get<double>());
      EXPECT_EQ(v2.occluders[i].map_points[k].y(), surfaces[i]["points"][k][1].get<double>());
    }
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
