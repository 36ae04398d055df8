// The library behind refloc-config-check: which service reads a --config file, and that the
// services' own loaders judge it (the deployed files pass, a semantic error is named).

#include "config_check.hpp"

#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigCheckLibrary, ServiceComesFromTheNameOrTheFileStem) {
  EXPECT_EQ(split_config_argument("/x/reflector_matcher.json"),
            std::make_pair(std::string("reflector_matcher"), std::string("/x/reflector_matcher.json")));
  EXPECT_EQ(split_config_argument("pose_solver=/tmp/a.json"),
            std::make_pair(std::string("pose_solver"), std::string("/tmp/a.json")));
  EXPECT_THAT(error_of([] { split_config_argument("/tmp/mine.json"); }),
              HasSubstr("/tmp/mine.json: cannot tell which service reads it; name it as SERVICE=FILE"));
}

TEST(ConfigCheckLibrary, EveryDeployedServiceConfigPasses) {
  for (const std::string& service : checkable_services()) {
    SCOPED_TRACE(service);
    const std::string path = kConfigDir + service + ".json";
    EXPECT_THAT(check_config_file(service, path).summary, HasSubstr("ok, " + service)) << path;
  }
}

TEST(ConfigCheckLibrary, SemanticErrorIsNamedByTheServicesLoader) {
  const std::string path = ::testing::TempDir() + "/check_sigma.json";
  std::ofstream(path) << R"({"clustering": {"range_sigma_m": 0}})";
  EXPECT_THAT(
      error_of([&] { check_config_file("reflector_extractor", path); }),
      HasSubstr(path + ": /clustering/range_sigma_m: expected a finite number in (0, 0.5], got 0 (0 would "
                       "split every cluster: nothing detected)"));
}

TEST(ConfigCheckLibrary, MatcherConfigAlsoChecksItsMap) {
  const std::string dir = ::testing::TempDir();
  std::ofstream(dir + "/bad_map.json")
      << R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 0, "y": 0},
                                            {"id": 3, "x": 5, "y": 5}]})";
  std::ofstream(dir + "/matcher.json") << R"({"map_file": "bad_map.json"})";
  EXPECT_THAT(error_of([&] { check_config_file("reflector_matcher", dir + "/matcher.json"); }),
              HasSubstr("bad_map.json: /reflectors/1: reflector id 2 is 0.000 m from id 1"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
