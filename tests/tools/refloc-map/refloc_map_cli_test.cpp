// The refloc-map binary: import -> info -> export on files, exit codes (0, 2 bad file with
// file:line, 64 usage), no silent overwrite.

#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

const std::string kTool = std::string(REFLOC_BINARY_DIR) + "/bin/refloc-map";

std::string fresh_dir(const std::string& name) {
  const auto dir =
      std::filesystem::temp_directory_path() / ("refloc_map_cli_" + std::to_string(::getpid())) / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(ReflocMapCli, ImportInfoExportRoundTrip) {
  const std::string dir = fresh_dir("round_trip");
  std::ofstream(dir + "/hall_c.csv")
      << "id,x,y,radius_m,sigma_m\n1,1.5,0.1,,0.002\n2,5.2,0.1,,\n3,9.1,11.9,0.05,\n";
  auto r = testing::run_command(kTool + " import --csv " + dir + "/hall_c.csv --out " + dir + "/map.json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output,
              HasSubstr("map.json: map hall_c version 1, imported, 3 reflectors (1 with covariance)"));
  r = testing::run_command(kTool + " info --map " + dir + "/map.json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("format 2, map hall_c version 1, imported, created 20"));
  EXPECT_THAT(r.output, HasSubstr("3 reflectors (1 with covariance, 2 without), 0 occluders"));
  EXPECT_THAT(r.output, HasSubstr("reflectors span x [1.500, 9.100] m, y [0.100, 11.900] m"));
  EXPECT_THAT(r.output, HasSubstr("largest sigma of a centre: median 2.00 mm, worst 2.00 mm (id 1)"));
  r = testing::run_command(kTool + " export --map " + dir + "/map.json --csv " + dir + "/out.csv");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir + "/out.csv");
  const std::string csv((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(csv,
            "id,x,y,radius_m,sigma_x_m,sigma_y_m,correlation_xy,type\n1,1.5,0.1,0.06,0.002,0.002,0,\n"
            "2,5.2,0.1,0.06,,,,\n3,9.1,11.9,0.05,,,,\n");
}

TEST(ReflocMapCli, ExitCodesAndNoSilentOverwrite) {
  const std::string dir = fresh_dir("exit_codes");
  std::ofstream(dir + "/bad.csv") << "1,0,0\n2,5,0\n3,0,four\n";
  auto r = testing::run_command(kTool + " import --csv " + dir + "/bad.csv --out " + dir + "/map.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("refloc-map: error: " + dir + "/bad.csv:3: y: expected a number"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/map.json"));
  r = testing::run_command(kTool + " info --map " + dir + "/missing.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  r = testing::run_command(kTool + " info --map " + std::string(REFLOC_SOURCE_DIR) +
                           "/deploy/config/map_demo.json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("format 1 (no header)"));
  r = testing::run_command(kTool + " import --csv " + dir + "/bad.csv");
  EXPECT_EQ(r.exit_code, 64) << r.output;
  r = testing::run_command(kTool);
  EXPECT_EQ(r.exit_code, 64) << r.output;
  std::ofstream(dir + "/good.csv") << "1,0,0\n2,5,0\n3,0,4\n";
  std::ofstream(dir + "/taken.json") << "{}";
  r = testing::run_command(kTool + " import --csv " + dir + "/good.csv --out " + dir + "/taken.json");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr("taken.json: exists; give --force to replace it"));
  r = testing::run_command(kTool + " import --force --map-id yard --csv " + dir + "/good.csv --out " + dir +
                           "/taken.json");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("map yard version 1"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
