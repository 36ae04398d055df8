// CSV import and export: columns by position or by header, comments, every bad line named by
// file:line and reason, sigma_m as an isotropic covariance, export -> import gives the map back.

#include "reflector_csv.hpp"

#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const CsvImportOptions kOptions{"hall_b", 0.05};

std::string error_of(const std::string& text) {
  try {
    import_reflector_csv(text, "survey.csv", kOptions);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ReflectorCsv, ImportsPositionalColumnsWithCommentsAndDefaults) {
  const ReflectorMap map = import_reflector_csv(
      "# total station, hall B\n1, 1.5, 0.1\n\n2,5.2,0.1,0.06   # bigger\n3,9.1,11.9,,0.002\r\n", "s.csv",
      kOptions);
  EXPECT_EQ(map.info.format, 2);
  EXPECT_EQ(map.info.map_id, "hall_b");
  EXPECT_EQ(map.info.version, 1);
  EXPECT_EQ(map.info.source, "imported");
  EXPECT_TRUE(is_iso8601_utc(map.info.created));
  ASSERT_EQ(map.reflectors.size(), 3u);
  EXPECT_EQ(map.reflectors[0].map_p_center, Eigen::Vector2d(1.5, 0.1));
  EXPECT_EQ(map.reflectors[0].radius, 0.05);
  EXPECT_EQ(map.reflectors[1].radius, 0.06);
  EXPECT_FALSE(map.reflectors[1].map_cov_center.has_value());
  ASSERT_TRUE(map.reflectors[2].map_cov_center.has_value());
  EXPECT_DOUBLE_EQ((*map.reflectors[2].map_cov_center)(0, 0), 4e-6);
  EXPECT_DOUBLE_EQ((*map.reflectors[2].map_cov_center)(1, 1), 4e-6);
  EXPECT_EQ((*map.reflectors[2].map_cov_center)(0, 1), 0.0);
}

TEST(ReflectorCsv, HeaderNamesColumnsInAnyOrder) {
  const ReflectorMap map = import_reflector_csv(
      "y,x,id,sigma_m,type\n0.1,1.5,1,0.001,foil\n0.1,5.2,2,,\n11.9,9.1,3,0.003,\"cyl, 120\"\n", "s.csv",
      kOptions);
  ASSERT_EQ(map.reflectors.size(), 3u);
  EXPECT_EQ(map.reflectors[0].id, 1);
  EXPECT_EQ(map.reflectors[0].map_p_center, Eigen::Vector2d(1.5, 0.1));
  EXPECT_EQ(map.reflectors[0].type, "foil");
  EXPECT_EQ(map.reflectors[2].type, "cyl, 120");
  EXPECT_FALSE(map.reflectors[1].map_cov_center.has_value());
}

TEST(ReflectorCsv, BadLinesAreNamedByFileLineAndReason) {
  EXPECT_THAT(error_of("1,0,0\n2,5,0\n3,0,x4\n"),
              HasSubstr("survey.csv:3: y: expected a number in [-100000, 100000"));
  EXPECT_THAT(error_of("1,0,0\n2,5\n"),
              HasSubstr("survey.csv:2: expected id,x,y[,radius_m][,sigma_m] (3 to 5 "
                        "fields), got 2"));
  EXPECT_THAT(error_of("1,0,0,0.06,0.001,7\n"), HasSubstr("survey.csv:1: expected id,x,y"));
  EXPECT_THAT(error_of("1,0,0\n1,5,0\n3,0,4\n"), HasSubstr("survey.csv:2: duplicate id 1 (first at line 1)"));
  EXPECT_THAT(error_of("1.5,0,0\n"), HasSubstr("survey.csv:1: id: expected an integer, got 1.5"));
  EXPECT_THAT(error_of("1,0,0,0\n"),
              HasSubstr("survey.csv:1: radius_m: expected a number in [0.001, 5], got \"0\""));
  EXPECT_THAT(error_of("1,0,0,,0\n"),
              HasSubstr("survey.csv:1: sigma_m: expected a number in (0, 100], got \"0\""));
  EXPECT_THAT(error_of("1,nan,0\n"), HasSubstr("survey.csv:1: x: expected a number"));
  EXPECT_THAT(error_of("id,x,z\n1,0,0\n"),
              HasSubstr("survey.csv:1: unknown column \"z\" (known: id, x, y, radius_m"));
  EXPECT_THAT(error_of("id,x\n1,0\n"), HasSubstr("survey.csv:1: the header has no column \"y\""));
  EXPECT_THAT(error_of("id,x,y,sigma_m,sigma_x_m,sigma_y_m\n"),
              HasSubstr("survey.csv:1: give sigma_m (isotropic) or"));
  EXPECT_THAT(error_of("id,x,y\n1,0,0,7\n"), HasSubstr("survey.csv:2: 4 fields, the header names 3"));
  EXPECT_THAT(error_of("id,x,y,type\n1,0,0,\"open\n"),
              HasSubstr("survey.csv:2: a quoted field is not closed"));
  EXPECT_THAT(error_of("# nothing\n\n"), HasSubstr("survey.csv: no reflector lines"));
}

TEST(ReflectorCsv, MapReadersRefusalNamesTheCsvLines) {
  EXPECT_THAT(error_of("# two\n1,0,0\n2,5,0\n"),
              HasSubstr("survey.csv: expected at least 3 reflectors, got 2"));
  EXPECT_THAT(error_of("1,0,0\n2,5,0\n\n3,0.05,0\n"),
              HasSubstr("survey.csv:4: reflector id 3 is 0.050 m from id 1 at line 1"));
}

TEST(ReflectorCsv, ExportThenImportGivesTheSameReflectors) {
  ReflectorMap map;
  map.info = MapInfo{2, "x", 4, "2026-12-03T06:30:58Z", "surveyed"};
  for (int i = 0; i < 5; ++i) {
    MapReflector r;
    r.id = 10 + i;
    r.map_p_center = {i * 3.0 + 1.0 / 3.0, (i % 2) * 7.0 - 2.0 / 7.0};
    r.radius = i == 2 ? 0.045 : 0.06;
    r.type = i == 1 ? "tape, \"wide\"" : "";
    if (i % 2 == 0) {
      Eigen::Matrix2d cov;
      cov << 4e-6, -1.5e-6, -1.5e-6, 9e-6;
      r.map_cov_center = cov;
    }
    map.reflectors.push_back(r);
  }
  const std::string csv = reflector_csv_text(map);
  EXPECT_THAT(csv, HasSubstr("id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type\n"));
  EXPECT_THAT(csv, HasSubstr("\n10,0.3333333333333333,-0.2857142857142857,0.06,0.002,0.003,-0.25,\n"));
  EXPECT_THAT(csv, HasSubstr("\n11,3.3333333333333335,6.714285714285714,0.06,,,,\"tape, \"\"wide\"\"\"\n"));
  const ReflectorMap back = import_reflector_csv(csv, "export.csv", kOptions);
  ASSERT_EQ(back.reflectors.size(), map.reflectors.size());
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    EXPECT_EQ(back.reflectors[i].id, map.reflectors[i].id);
    EXPECT_EQ(back.reflectors[i].map_p_center, map.reflectors[i].map_p_center);
    EXPECT_EQ(back.reflectors[i].radius, map.reflectors[i].radius);
    EXPECT_EQ(back.reflectors[i].type, map.reflectors[i].type);
    ASSERT_EQ(back.reflectors[i].map_cov_center.has_value(), map.reflectors[i].map_cov_center.has_value());
    if (map.reflectors[i].map_cov_center) {
      EXPECT_TRUE(back.reflectors[i].map_cov_center->isApprox(*map.reflectors[i].map_cov_center, 1e-14));
    }
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
