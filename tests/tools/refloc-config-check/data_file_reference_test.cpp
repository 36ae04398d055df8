// refloc-config-check --print-reference: the data files' key tables come from their own readers,
// every key has a meaning, and every key the shipped demo files use is in the table.

#include "data_file_reference.hpp"

#include "common/json_config.hpp"
#include "common/reflector_map.hpp"
#include "mission_file.hpp"
#include "world_renderer/world_loader.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <regex>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

TEST(DataFileReference, EveryKindHasATableWithAMeaningOnEveryRow) {
  for (const std::string& kind : data_file_kinds()) {
    const std::string table = data_file_reference_markdown(kind);
    EXPECT_THAT(table, ::testing::StartsWith("| key |")) << kind;
    // The same test as docs_parameters_reference: a row whose last column is empty.
    EXPECT_FALSE(std::regex_search(table, std::regex(R"(\| `[^`]+` \|.*\|  \|\n)"))) << kind << "\n" << table;
  }
  EXPECT_THROW(data_file_reference_markdown("robot"), ConfigError);
}

TEST(DataFileReference, ShippedDemoFilesUseOnlyKeysOfTheTable) {
  const JsonConfig map = JsonConfig::load_file(kConfigDir + "map_demo.json");
  parse_reflector_map(map);
  const JsonConfig map_v2 = JsonConfig::load_file(kConfigDir + "map_demo_v2.json");
  parse_reflector_map(map_v2);
  const JsonConfig world = JsonConfig::load_file(kConfigDir + "world_demo.json");
  sim::parse_world(world, "", kConfigDir);
  const JsonConfig mission = JsonConfig::load_file(kConfigDir + "mission_demo.json");
  parse_mission(mission);
  const std::pair<const JsonConfig*, std::string> files[] = {
      {&map, "map"}, {&map_v2, "map"}, {&world, "world"}, {&mission, "mission"}};
  for (const auto& [file, kind] : files) {
    const std::string table = data_file_reference_markdown(kind);
    ASSERT_FALSE(file->key_records().empty()) << kind;
    for (const ConfigKeyRecord& key : file->key_records())
      EXPECT_THAT(table, ::testing::HasSubstr("| `" + key.pointer + "` |")) << kind;
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
