// Hostile files against real binaries (issue 11 "Bad files"): a service (reflector_extractor
// for config files, reflector_matcher for maps) and refloc-config-check must both exit 2
// with exactly one line on stderr naming the file (and the key), before touching LCM.
// Each run is killed after kHangGuardS, so a FIFO that blocks fails the test instead of
// hanging it; the time each run took is printed (the bound asserted is only a hang guard:
// the numbers to quote are in the README).

#include <sys/stat.h>
#include <unistd.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

constexpr int kHangGuardS = 20;  // generous: sanitized builds on a loaded CI machine
const std::string kBin = std::string(REFLOC_BINARY_DIR) + "/bin/";
const std::string kConfigDir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";

// ctest runs each test of this file as its own process, two at a time: one directory per
// process, or two tests read each other's stderr files (seen in CI: one test's FIFO message in
// another's capture).
const std::string& scratch_dir() {
  static const std::string dir = [] {
    std::string path = ::testing::TempDir() + "refloc_hostile_XXXXXX";
    if (mkdtemp(path.data()) == nullptr)
      throw std::runtime_error("mkdtemp failed in " + ::testing::TempDir());
    return path;
  }();
  return dir;
}

struct ProcessRun {
  int exit_code = -1;
  std::string stderr_text;
  double seconds = 0.0;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

ProcessRun run_service(const std::string& args) {
  const std::string err = scratch_dir() + "/hostile_stderr.txt";
  // No LCM in this test's environment: a binary that got as far as LCM would say so.
  const std::string command = "timeout -s KILL " + std::to_string(kHangGuardS) + " " + args +
                              " --lcm-url 'udpm://239.255.76.67:7667?ttl=0' >/dev/null 2>" + err;
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(command.c_str());
  ProcessRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.stderr_text = slurp(err);
  return r;
}

ProcessRun run_tool(const std::string& args) {
  const std::string err = scratch_dir() + "/hostile_tool_stderr.txt";
  const auto t0 = std::chrono::steady_clock::now();
  const int status = std::system(("timeout -s KILL " + std::to_string(kHangGuardS) + " " + kBin +
                                  "refloc-config-check " + args + " >/dev/null 2>" + err)
                                     .c_str());
  ProcessRun r;
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.stderr_text = slurp(err);
  return r;
}

void expect_one_line_exit_2(const ProcessRun& r, const std::string& what, const std::string& file,
                            const std::string& detail) {
  std::printf("[ timing ] %-45s %.3f s exit %d\n", what.c_str(), r.seconds, r.exit_code);
  EXPECT_EQ(r.exit_code, 2) << what << ": " << r.stderr_text;
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << what << ": " << r.stderr_text;
  EXPECT_THAT(r.stderr_text, HasSubstr(file + ": " + detail)) << what;
  EXPECT_LT(r.seconds, kHangGuardS - 1) << what;
}

std::string write(const std::string& name, const std::string& text) {
  const std::string path = scratch_dir() + "/hostile_" + name;
  std::ofstream(path) << text;
  return path;
}

void check_config(const std::string& what, const std::string& path, const std::string& detail) {
  expect_one_line_exit_2(run_service(kBin + "reflector_extractor --config " + path),
                         "reflector_extractor: " + what, path, detail);
  expect_one_line_exit_2(run_tool("--config reflector_extractor=" + path), "refloc-config-check: " + what,
                         path, detail);
}

void check_map(const std::string& what, const std::string& path, const std::string& detail) {
  expect_one_line_exit_2(
      run_service(kBin + "reflector_matcher --config " + kConfigDir + "reflector_matcher.json --robot " +
                  kConfigDir + "robot.json --map " + path),
      "reflector_matcher: " + what, path, detail);
  expect_one_line_exit_2(run_tool("--map " + path), "refloc-config-check: " + what, path, detail);
}

std::string reflectors_at_one_spot(int n) {
  std::string list;
  for (int i = 0; i < n; ++i) list += (i ? "," : "") + ("{\"id\":" + std::to_string(i) + ",\"x\":1,\"y\":1}");
  return "{\"reflectors\":[" + list + "]}";
}

TEST(HostileFiles, HundredThousandLevelsOfNesting) {
  const std::string deep = "{\"a\":" + std::string(100000, '[') + std::string(100000, ']') + "}";
  const std::string path = write("deep.json", deep);
  check_config("100,000-deep nesting", path, "/a/0/0/0");
  check_map("100,000-deep nesting", path, "/a/0/0/0");
}

TEST(HostileFiles, FifoIsRefusedWithoutBlocking) {
  const std::string path = scratch_dir() + "/hostile_fifo.json";
  ::unlink(path.c_str());
  ASSERT_EQ(::mkfifo(path.c_str(), 0600), 0);
  check_config("FIFO", path, "is a FIFO");
  check_map("FIFO", path, "is a FIFO");
  ::unlink(path.c_str());
}

TEST(HostileFiles, DevZeroAndADirectoryAreRefused) {
  check_config("/dev/zero", "/dev/zero", "is a character device");
  const std::string dir = scratch_dir() + "/hostile_dir.json";
  ::mkdir(dir.c_str(), 0700);
  check_config("directory", dir, "is a directory");
}

TEST(HostileFiles, HugeFileIsRefusedUnread) {
  const std::string path = write("huge.json", "{}");
  ASSERT_EQ(::truncate(path.c_str(), 1LL << 30), 0);  // 1 GiB, sparse
  check_config("1 GiB file", path, "larger than 4194304 bytes");
  ::unlink(path.c_str());
}

TEST(HostileFiles, UnknownKeyHoldingEmptyObjectOrArray) {
  check_config("unknown key {}", write("unknown_object.json", R"({"clustering": {}, "typo": {}})"),
               "/typo: unknown key");
  check_config("unknown key []", write("unknown_array.json", R"({"typo": []})"), "/typo: unknown key");
}

TEST(HostileFiles, RangeSigmaZeroWouldDetectNothing) {
  check_config("range_sigma_m 0", write("sigma0.json", R"({"clustering": {"range_sigma_m": 0}})"),
               "/clustering/range_sigma_m: expected a finite number in (0, 0.5], got 0");
}

TEST(HostileFiles, AllReflectorsAtOneSpot) {
  check_map("3 reflectors at one spot", write("one_spot.json", reflectors_at_one_spot(3)),
            "/reflectors/1: reflector id 1 is 0.000 m from id 0");
}

TEST(HostileFiles, HundredThousandReflectorsAtOneSpot) {
  check_map("100,000 reflectors at one spot", write("one_spot_100k.json", reflectors_at_one_spot(100000)),
            "/reflectors/1: reflector id 1 is 0.000 m from id 0");
}

TEST(HostileFiles, ColinearMapWarnsAndFailsOnlyWhenStrict) {
  const std::string path =
      write("colinear.json", R"({"reflectors": [{"id": 1, "x": 0, "y": 0}, {"id": 2, "x": 4, "y": 0},
                                               {"id": 3, "x": 8, "y": 0}, {"id": 4, "x": 12, "y": 0}]})");
  const ProcessRun warn = run_tool("--map " + path);
  EXPECT_EQ(warn.exit_code, 0) << warn.stderr_text;
  EXPECT_THAT(warn.stderr_text,
              HasSubstr("warning: " + path + ": all 4 reflectors lie within 0.000 m of one line"));
  EXPECT_EQ(std::count(warn.stderr_text.begin(), warn.stderr_text.end(), '\n'), 1);
  expect_one_line_exit_2(run_tool("--strict --map " + path), "refloc-config-check --strict: colinear map",
                         path, "all 4 reflectors lie within");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
