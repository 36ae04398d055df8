// Writing format-2 maps: write -> load gives the same map (doubles bit for bit, covariance,
// occluders), the write is atomic, and a map the reader would refuse is not written.

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

std::string temp_dir() {
  const auto dir =
      std::filesystem::temp_directory_path() / ("refloc_map_writer_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

ReflectorMap awkward_map() {
  ReflectorMap map;
  map.info = MapInfo{2, "hall \"A\"", 7, "2026-12-03T06:30:58.25Z", "surveyed"};
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  for (int i = 0; i < 40; ++i) {
    MapReflector r;
    r.id = 100 + i;
    // Doubles with no short decimal form: only a shortest round-trip print keeps them.
    r.map_p_center = Eigen::Vector2d(i * 2.0 + coordinate(rng) * 1e-3, coordinate(rng) + 1.0 / 3.0);
    r.radius = i % 3 == 0 ? 0.045 : 0.06;
    if (i % 4 == 0) r.type = "foil_90";
    if (i % 2 == 0) {
      Eigen::Matrix2d cov;
      cov << 1.0 / 7.0 * 1e-5, -1e-7 / 3.0, -1e-7 / 3.0, 2.0 / 3.0 * 1e-5;
      r.map_cov_center = cov;
    }
    map.reflectors.push_back(r);
  }
  map.occluders.push_back(MapOccluder{"hall", {{0.0, 0.0}, {20.0, 0.0}, {20.0, 12.0 / 7.0}}, true});
  map.occluders.push_back(MapOccluder{"rack 1", {{5.0, 5.2}, {9.1, 5.2}}, false});
  return map;
}

TEST(ReflectorMapWriter, WriteThenLoadGivesTheSameMap) {
  const ReflectorMap map = awkward_map();
  const std::string path = temp_dir() + "/round_trip.json";
  write_reflector_map(map, path);
  const ReflectorMap back = load_reflector_map(path);
  EXPECT_EQ(back.info.format, 2);
  EXPECT_EQ(back.info.map_id, map.info.map_id);
  EXPECT_EQ(back.info.version, 7);
  EXPECT_EQ(back.info.created, map.info.created);
  EXPECT_EQ(back.info.source, "surveyed");
  ASSERT_EQ(back.reflectors.size(), map.reflectors.size());
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    const MapReflector& a = map.reflectors[i];
    const MapReflector& b = back.reflectors[i];
    EXPECT_EQ(b.id, a.id);
    EXPECT_EQ(b.map_p_center, a.map_p_center) << "reflector " << a.id;  // exact, not near
    EXPECT_EQ(b.radius, a.radius);
    EXPECT_EQ(b.type, a.type);
    ASSERT_EQ(b.map_cov_center.has_value(), a.map_cov_center.has_value());
    if (a.map_cov_center) {
      EXPECT_EQ(*b.map_cov_center, *a.map_cov_center);
    }
  }
  ASSERT_EQ(back.occluders.size(), 2u);
  EXPECT_EQ(back.occluders[0].name, "hall");
  EXPECT_TRUE(back.occluders[0].closed);
  EXPECT_FALSE(back.occluders[1].closed);
  EXPECT_EQ(back.occluders[0].map_points, map.occluders[0].map_points);
  EXPECT_EQ(back.occluders[1].map_points, map.occluders[1].map_points);
  EXPECT_EQ(reflector_map_v2_text(back), reflector_map_v2_text(map));
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp-" + std::to_string(::getpid())));
}

TEST(ReflectorMapWriter, FormatOneMapIsWrittenAsFormatTwo) {
  const ReflectorMap v1 = load_reflector_map(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json");
  ReflectorMap map = v1;
  map.info = MapInfo{1, "demo_hall", 1, "", "typed"};
  const std::string text = reflector_map_v2_text(map);
  EXPECT_THAT(text, HasSubstr("\"format\": 2,"));
  EXPECT_THAT(text, HasSubstr("\"default_radius_m\": 0.06,"));
  EXPECT_THAT(text, HasSubstr("{\"id\": 1, \"x\": 1.5, \"y\": 0.1},"));
  const ReflectorMap back = parse_reflector_map(JsonConfig::parse_text(text, "text"));
  EXPECT_TRUE(is_iso8601_utc(back.info.created)) << back.info.created;  // empty created: now
  ASSERT_EQ(back.reflectors.size(), 24u);
  EXPECT_EQ(back.reflectors[23].map_p_center, v1.reflectors[23].map_p_center);
}

TEST(ReflectorMapWriter, MapTheReaderWouldRefuseIsNotWritten) {
  ReflectorMap map = awkward_map();
  map.reflectors.resize(2);
  const std::string path = temp_dir() + "/refused.json";
  try {
    write_reflector_map(map, path);
    FAIL() << "a 2-reflector map was written";
  } catch (const ConfigError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("refused.json (not written): /reflectors: expected at least 3 reflectors"));
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  map = awkward_map();
  map.info.map_id = "";
  EXPECT_THROW(write_reflector_map(map, path), ConfigError);
  EXPECT_FALSE(std::filesystem::exists(path));
}

TEST(ReflectorMapWriter, ReplacesAnExistingFileAndNamesAnUnwritablePath) {
  const std::string path = temp_dir() + "/replaced.json";
  std::ofstream(path) << "old";
  write_reflector_map(awkward_map(), path);
  EXPECT_EQ(load_reflector_map(path).reflectors.size(), 40u);
  try {
    write_reflector_map(awkward_map(), "/nonexistent_dir_refloc/map.json");
    FAIL() << "wrote into a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("/nonexistent_dir_refloc/map.json.tmp-"));
    EXPECT_THAT(e.what(), HasSubstr("cannot write the map: No such file or directory"));
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
