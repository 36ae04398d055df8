#include "common/reflector_map.hpp"
#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

std::string map_error(const char* text) {
  try {
    const JsonConfig c(nlohmann::json::parse(text), "map.json");
    parse_reflector_map(c);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ReflectorMap, ParsesIdsPositionsAndDefaultRadius) {
  const JsonConfig c(nlohmann::json::parse(R"({"default_radius_m": 0.05, "reflectors": [
      {"id": 3, "x": 1.0, "y": 2.0}, {"id": 7, "x": -1.5, "y": 0.25, "radius_m": 0.06},
      {"id": 9, "x": 0, "y": 0}]})"),
                     "map.json");
  const ReflectorMap map = parse_reflector_map(c);
  ASSERT_EQ(map.reflectors.size(), 3u);
  EXPECT_EQ(map.reflectors[1].id, 7);
  EXPECT_DOUBLE_EQ(map.reflectors[1].map_p_center.x(), -1.5);
  EXPECT_DOUBLE_EQ(map.reflectors[0].radius, 0.05);
  EXPECT_DOUBLE_EQ(map.reflectors[1].radius, 0.06);
  EXPECT_EQ(map.index_of(9), 2);
  EXPECT_EQ(map.index_of(4), -1);
}

TEST(ReflectorMap, DuplicateIdNamesBothPlaces) {
  EXPECT_THAT(map_error(R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 1, "y": 0},
                                          {"id": 1, "x": 2, "y": 0}]})"),
              HasSubstr("map.json: /reflectors/2/id: duplicate reflector id 1 (also at /reflectors/0)"));
}

TEST(ReflectorMap, FewerThanThreeReflectorsIsAnError) {
  EXPECT_THAT(map_error(R"({"reflectors": [{"id": 1, "x": 0, "y": 0}]})"),
              HasSubstr("/reflectors: expected at least 3 reflectors, got 1"));
}

TEST(ReflectorMap, MissingCoordinateAndBadRadiusAreNamed) {
  EXPECT_THAT(map_error(R"({"reflectors": [{"id": 1, "x": 0}, {"id": 2, "x": 1, "y": 0},
                                          {"id": 3, "x": 2, "y": 0}]})"),
              HasSubstr("/reflectors/0/y: missing"));
  EXPECT_THAT(
      map_error(R"({"reflectors": [{"id": 1, "x": 0, "y": 0, "radius_m": 0}, {"id": 2, "x": 1, "y": 0},
                                          {"id": 3, "x": 2, "y": 0}]})"),
      HasSubstr("/reflectors/0/radius_m: expected a finite number in [0.001, 5]"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
