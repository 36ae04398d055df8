// refloc-config-check over the maps we ship: every deploy/config/map_*.json passes, and
// one broken file among good ones stops the run with exit 2 naming that file.

#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const std::string kTool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-config-check";

std::vector<std::string> deployed_maps() {
  std::vector<std::string> maps;
  for (const auto& entry :
       std::filesystem::directory_iterator(std::string(REFLOC_SOURCE_DIR) + "/deploy/config")) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("map_", 0) == 0 && entry.path().extension() == ".json")
      maps.push_back(entry.path().string());
  }
  std::sort(maps.begin(), maps.end());
  return maps;
}

TEST(ConfigCheckTool, EveryDeployedMapIsValid) {
  const auto maps = deployed_maps();
  ASSERT_GE(maps.size(), 3u) << "map_demo, map_paper_cell, map_symmetric";
  std::string command = kTool;
  for (const auto& m : maps) command += " --map " + m;
  const auto r = testing::run_command(command);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  for (const auto& m : maps) EXPECT_THAT(r.output, HasSubstr(m + ": ok, ")) << r.output;
}

TEST(ConfigCheckTool, ABrokenMapAmongGoodOnesExitsTwoNamingIt) {
  const std::string bad = ::testing::TempDir() + "/broken_map.json";
  std::ofstream(bad) << R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 1, "x": 4, "y": 0}]})";
  const auto maps = deployed_maps();
  ASSERT_FALSE(maps.empty());
  const auto r = testing::run_command(kTool + " --map " + maps.front() + " --map " + bad);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(maps.front() + ": ok, "));
  EXPECT_THAT(r.output, HasSubstr(bad + ": "));
}

TEST(ConfigCheckTool, PrintsTheFormatTwoHeaderAndCounts) {
  const std::string v2 = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo_v2.json";
  const std::string v1 = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json";
  const auto r = testing::run_command(kTool + " --map " + v2 + " --map " + v1);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr(v2 + ": ok, 24 reflectors (0 with covariance, 24 without), 5 occluders, format "
                             "2, map demo_hall version 1, typed, created 2026-12-03T07:00:00Z"));
  EXPECT_THAT(r.output, HasSubstr(v1 + ": ok, 24 reflectors, format 1"));
}

TEST(ConfigCheckTool, TheSymmetricMapWarnsThatItLocalizesNowhereTheDemoMapDoesNot) {
  const std::string symmetric = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_symmetric.json";
  const std::string demo = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo_v2.json";
  const auto r = testing::run_command(kTool + " --map " + symmetric + " --map " + demo);
  EXPECT_EQ(r.exit_code, 0) << r.output;  // a warning, not an invalid file
  EXPECT_THAT(r.output, HasSubstr("warning: " + symmetric + ": the layout localizes nowhere: blind "));
  EXPECT_THAT(r.output, ::testing::Not(HasSubstr("warning: " + demo)));
  const auto strict = testing::run_command(kTool + " --strict --map " + symmetric);
  EXPECT_EQ(strict.exit_code, 2) << strict.output;
}

TEST(ConfigCheckTool, NoMapIsAUsageError) {
  const auto r = testing::run_command(kTool);
  EXPECT_EQ(r.exit_code, 64) << "usage error (exit 2 is reserved for invalid files): " << r.output;
  EXPECT_THAT(r.output, HasSubstr("--map"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
