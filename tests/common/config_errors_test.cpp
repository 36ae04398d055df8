// The process-level contract for bad files: exit code 2 and one message naming
// the file, the JSON pointer and what was expected; never a crash or a trace.

#include "tests/tools/run_command.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;
using ::testing::Not;

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::ofstream(path) << text;
  return path;
}

testing::CommandResult check_map(const std::string& path) {
  return testing::run_command(std::string(REFLOC_BINARY_DIR) + "/bin/refloc-config-check --map " + path);
}

void expect_config_error(const testing::CommandResult& r, const std::string& file,
                         const std::string& detail) {
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(file + ": " + detail));
  EXPECT_THAT(r.output, Not(HasSubstr("terminate")));
  EXPECT_THAT(r.output, Not(HasSubstr("what()")));
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << "one message line: " << r.output;
}

TEST(ConfigErrors, ValidMapExitsZero) {
  const auto path = write_file("good_map.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  const auto r = check_map(path);
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("ok, 3 reflectors"));
}

TEST(ConfigErrors, MissingKey) {
  const auto path = write_file("missing_key.json", R"({"reflectors": [{"id": 1, "x": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  expect_config_error(check_map(path), path, "/reflectors/0/y: missing; expected a number");
}

TEST(ConfigErrors, WrongType) {
  const auto path = write_file("wrong_type.json", R"({"reflectors": [{"id": 1, "x": "0", "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  expect_config_error(check_map(path), path, "/reflectors/0/x: expected a number");
}

TEST(ConfigErrors, OutOfRangeValue) {
  const auto path =
      write_file("out_of_range.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0, "radius_m": -0.06},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  expect_config_error(check_map(path), path,
                      "/reflectors/0/radius_m: expected a finite number in [0.001, 5]");
}

TEST(ConfigErrors, NanIsNotANumber) {
  // JSON cannot spell NaN; files written by tools that try carry NaN or "NaN".
  const auto bare = write_file("nan_bare.json", R"({"reflectors": [{"id": 1, "x": NaN, "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  const auto r = check_map(bare);
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_THAT(r.output, HasSubstr(bare + ": not valid JSON"));
  const auto quoted = write_file("nan_string.json", R"({"reflectors": [{"id": 1, "x": "NaN", "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  expect_config_error(check_map(quoted), quoted, "/reflectors/0/x: expected a number");
  const auto overflow = write_file("inf.json", R"({"reflectors": [{"id": 1, "x": 1e999, "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  const auto r_overflow = check_map(overflow);
  EXPECT_EQ(r_overflow.exit_code, 2) << r_overflow.output;
  EXPECT_THAT(r_overflow.output, HasSubstr(overflow + ": not valid JSON"));
  EXPECT_THAT(r_overflow.output, HasSubstr("overflow"));
}

TEST(ConfigErrors, DuplicateReflectorId) {
  const auto path = write_file("duplicate.json", R"({"reflectors": [{"id": 5, "x": 0, "y": 0},
      {"id": 2, "x": 4, "y": 0}, {"id": 5, "x": 0, "y": 3}]})");
  expect_config_error(check_map(path), path, "/reflectors/2/id: duplicate reflector id 5");
}

TEST(ConfigErrors, UnknownKeyIsNotSilentlyIgnored) {
  const auto path = write_file("typo.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0, "radius": 0.06},
      {"id": 2, "x": 4, "y": 0}, {"id": 3, "x": 0, "y": 3}]})");
  expect_config_error(check_map(path), path, "/reflectors/0/radius: unknown key");
}

TEST(ConfigErrors, MissingFile) {
  expect_config_error(check_map("/nonexistent/map.json"), "/nonexistent/map.json", "cannot open");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
