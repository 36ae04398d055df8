// refloc-map merge: entries within the gate averaged (weighted by their covariances), the others
// added with fresh ids, a gate wider than the layout refused; the binary end to end.

#include "map_merge.hpp"

#include "common/json_config.hpp"
#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

MapReflector reflector(int id, double x, double y, double sigma_m) {
  MapReflector r;
  r.id = id;
  r.map_p_center = {x, y};
  r.map_cov_center = Eigen::Matrix2d::Identity() * sigma_m * sigma_m;
  return r;
}

ReflectorMap survey(std::vector<MapReflector> reflectors) {
  ReflectorMap map;
  map.info = {2, "cell", 1, "2026-12-05T00:00:00Z", "surveyed"};
  map.reflectors = std::move(reflectors);
  return map;
}

TEST(MapMerge, NearEntriesAreAveragedByTheirCovariancesOthersAddedWithNewIds) {
  // Two static surveys of one cell from two headings: 1 and 2 in both, 3 only in the first, the
  // second's 7 only in the second. The second saw reflector 2 twice as well (sigma 1 vs 2 mm).
  const ReflectorMap a =
      survey({reflector(1, 1.0, 0.1, 0.002), reflector(2, 3.0, 0.1, 0.002), reflector(3, 0.1, 2.0, 0.002)});
  const ReflectorMap b = survey(
      {reflector(5, 1.003, 0.1, 0.002), reflector(6, 3.0, 0.103, 0.001), reflector(7, 3.9, 2.0, 0.002)});
  const MapMergePlan plan = plan_map_merge({a, b}, {"a.json", "b.json"}, 0.1, "2026-12-06T00:00:00Z");
  ASSERT_EQ(plan.merged.reflectors.size(), 4u);
  EXPECT_EQ(plan.averaged, 2);
  EXPECT_EQ(plan.added, 1);
  EXPECT_NEAR(plan.merged.reflectors[0].map_p_center.x(), 1.0015, 1e-12);                   // equal weights
  EXPECT_NEAR(plan.merged.reflectors[1].map_p_center.y(), 0.1 + 0.003 * 4.0 / 5.0, 1e-12);  // 1/trace
  EXPECT_NEAR(plan.merged.reflectors[1].map_cov_center->trace(), 2e-6, 1e-15);  // the better input's
  EXPECT_EQ(plan.merged.reflectors[3].id, 4);  // the next free id, not the second map's 7
  EXPECT_EQ(plan.merged.info.version, 2);
  EXPECT_EQ(plan.merged.info.source, "merged");
  EXPECT_THAT(plan.lines[2], HasSubstr("b.json reflector 7 at (3.900, 2.000) matches none: added"));
}

TEST(MapMerge, TwoEntriesOfOneMapOnOneReflectorAreRefused) {
  const ReflectorMap a =
      survey({reflector(1, 1.0, 0.1, 0.002), reflector(2, 3.0, 0.1, 0.002), reflector(3, 0.1, 2.0, 0.002)});
  const ReflectorMap b =
      survey({reflector(5, 1.0, 0.1, 0.002), reflector(6, 1.2, 0.1, 0.002), reflector(7, 3.9, 2.0, 0.002)});
  try {
    plan_map_merge({a, b}, {"a.json", "b.json"}, 0.3, "2026-12-06T00:00:00Z");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("b.json: reflectors 5 and 6 both lie within --gate-m 0.300 m of reflector 1"));
  }
}

TEST(MapMerge, TwoNewEntriesOfOneMapOnOnePlaceAreRefusedToo) {
  // Neither matches the first map; the second lies within the gate of the first one's new entry.
  const ReflectorMap a =
      survey({reflector(1, 1.0, 0.1, 0.002), reflector(2, 3.0, 0.1, 0.002), reflector(3, 0.1, 2.0, 0.002)});
  const ReflectorMap b =
      survey({reflector(5, 3.9, 2.0, 0.002), reflector(6, 3.9, 2.05, 0.002), reflector(7, 1.0, 0.1, 0.002)});
  try {
    plan_map_merge({a, b}, {"a.json", "b.json"}, 0.1, "2026-12-06T00:00:00Z");
    FAIL() << "no error";
  } catch (const ConfigError& e) {
    EXPECT_THAT(e.what(),
                HasSubstr("b.json: reflectors 5 and 6 both lie within --gate-m 0.100 m of reflector 4"));
  }
}

TEST(MapMerge, TheBinaryWritesTheMergedMapAndRefusesToOverwriteOrOneMap) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("refloc_map_merge_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string tool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-map", d = dir.string();
  std::ofstream(d + "/a.csv") << "id,x,y\n1,1.0,0.1\n2,3.0,0.1\n3,0.1,2.0\n";
  std::ofstream(d + "/b.csv") << "id,x,y\n1,1.002,0.1\n2,3.0,0.1\n4,3.9,2.0\n";
  for (const char* m : {"a", "b"})
    ASSERT_EQ(
        testing::run_command(tool + " import --csv " + d + "/" + m + ".csv --out " + d + "/" + m + ".json")
            .exit_code,
        0);
  auto r = testing::run_command(tool + " merge " + d + "/a.json " + d + "/b.json --out " + d + "/m.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("m.json: map a version 2: 4 reflectors (2 entries averaged in, 1 added)"));
  const ReflectorMap merged = load_reflector_map(d + "/m.json");
  EXPECT_NEAR(merged.reflectors[0].map_p_center.x(), 1.001, 1e-12);
  r = testing::run_command(tool + " merge " + d + "/a.json " + d + "/b.json --out " + d + "/m.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;  // exists: --force
  r = testing::run_command(tool + " merge " + d + "/a.json --out " + d + "/n.json");
  EXPECT_EQ(r.exit_code, 64) << r.output;  // one map is no merge
  std::filesystem::remove_all(dir);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
