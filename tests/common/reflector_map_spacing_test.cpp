// Map geometry: reflectors that would touch are refused (also 100,000 at one spot, without
// a quadratic start), absurd values are refused, colinear maps load with a warning.

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;
using ::testing::IsEmpty;

std::string map_error(const std::string& text) {
  try {
    parse_reflector_map(JsonConfig::parse_text(text, "map.json"));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

std::string map_of(const std::string& reflectors) { return "{\"reflectors\": [" + reflectors + "]}"; }

TEST(ReflectorMapSpacing, AllReflectorsAtOneSpotAreRefused) {
  EXPECT_THAT(
      map_error(map_of(R"({"id": 1, "x": 2, "y": 3}, {"id": 2, "x": 2, "y": 3}, {"id": 3, "x": 2, "y": 3})")),
      HasSubstr("map.json: /reflectors/1: reflector id 2 is 0.000 m from id 1 at /reflectors/0; centres "
                "must be at least 0.130 m apart"));
}

TEST(ReflectorMapSpacing, CentresCloserThanTwoRadiiPlusTheGapAreRefused) {
  // 0.06 + 0.06 + 0.01 = 0.13 m: 0.129 m is refused, 0.131 m accepted.
  EXPECT_THAT(map_error(map_of(R"({"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 4, "y": 0},
                                 {"id": 3, "x": 0, "y": 3}, {"id": 4, "x": 4.129, "y": 0})")),
              HasSubstr("/reflectors/3: reflector id 4 is 0.129 m from id 2"));
  EXPECT_EQ(map_error(map_of(R"({"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 4, "y": 0},
                               {"id": 3, "x": 0, "y": 3}, {"id": 4, "x": 4.131, "y": 0})")),
            "");
}

TEST(ReflectorMapSpacing, EachReflectorsOwnRadiusCounts) {
  // A 0.5 m pillar next to a 0.06 m reflector at 0.5 m: 0.5 + 0.06 + 0.01 > 0.5.
  EXPECT_THAT(map_error(map_of(R"({"id": 1, "x": 0, "y": 0, "radius_m": 0.5}, {"id": 2, "x": 0.5, "y": 0},
                                 {"id": 3, "x": 0, "y": 3})")),
              HasSubstr("/reflectors/1: reflector id 2 is 0.500 m from id 1"));
}

TEST(ReflectorMapSpacing, HundredThousandAtOneSpotAreRefusedAtTheSecond) {
  std::string list;
  for (int i = 0; i < 100000; ++i)
    list += fmt::format("{}{{\"id\": {}, \"x\": 1, \"y\": 1}}", i ? "," : "", i);
  EXPECT_THAT(map_error(map_of(list)),
              HasSubstr("map.json: /reflectors/1: reflector id 1 is 0.000 m from id 0"));
}

TEST(ReflectorMapSpacing, TenThousandWellSpacedReflectorsLoad) {
  std::string list;
  for (int i = 0; i < 10000; ++i)
    list += fmt::format("{}{{\"id\": {}, \"x\": {}, \"y\": {}}}", i ? "," : "", i, (i % 100) * 0.2,
                        (i / 100) * 0.2);
  const ReflectorMap map = parse_reflector_map(JsonConfig::parse_text(map_of(list), "grid.json"));
  EXPECT_EQ(map.reflectors.size(), 10000u);
  EXPECT_THAT(map.warnings, IsEmpty());
}

TEST(ReflectorMapSpacing, AbsurdCoordinatesAndRadiiAreRefused) {
  EXPECT_THAT(map_error(map_of(
                  R"({"id": 1, "x": 1e6, "y": 0}, {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3})")),
              HasSubstr("/reflectors/0/x: expected a finite number in [-100000, 100000]"));
  EXPECT_THAT(map_error(map_of(R"({"id": 1, "x": 0, "y": 0, "radius_m": 50}, {"id": 2, "x": 400, "y": 0},
                                 {"id": 3, "x": 0, "y": 300})")),
              HasSubstr("/reflectors/0/radius_m: expected a finite number in [0.001, 5]"));
}

TEST(ReflectorMapSpacing, ColinearMapLoadsWithAWarning) {
  const ReflectorMap map = parse_reflector_map(JsonConfig::parse_text(
      map_of(R"({"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 4, "y": 0.01}, {"id": 3, "x": 8, "y": -0.02})"),
      "line.json"));
  ASSERT_EQ(map.warnings.size(), 1u);
  EXPECT_THAT(map.warnings[0], HasSubstr("line.json: all 3 reflectors lie within 0.020 m of one line"));
}

TEST(ReflectorMapSpacing, ThreeNonColinearReflectorsGiveNoWarning) {
  const ReflectorMap map = parse_reflector_map(JsonConfig::parse_text(
      map_of(R"({"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 8, "y": 0.2})"),
      "ok.json"));
  EXPECT_THAT(map.warnings, IsEmpty());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
