// The file deploy/load_test.sh writes for refloc-log --load-test: every record read
// with its unit, and a malformed one rejected naming file, line and record.

#include "load_test_samples.hpp"

#include "common/json_config.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;

LoadSamples parse(const std::string& text) {
  std::istringstream in(text);
  return parse_load_samples(in, "samples.txt");
}

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(LoadTestSamples, ReadsTheRunAndEveryProcessInOrder) {
  const LoadSamples s = parse(
      "# written by deploy/load_test.sh\n"
      "duration_s 600\nmeasured_s 600.42\ncores 2\nclock_ticks_per_s 100\nmax_p99_ms 5\nscan_rate_hz 50\n"
      "build /work/build\nlog /work/logs/refloc.0\nload_average_before 0.52 0.48 0.40\n"
      "load_average_after 1.90 1.20 0.70\n"
      "process robot_sim 12345 121 2478080 20480 22528 0\n"
      "process lcm-logger 300 121 1239040 10240 11264 1\n");
  EXPECT_DOUBLE_EQ(s.run.duration_s, 600.0);
  EXPECT_DOUBLE_EQ(s.run.measured_s, 600.42);
  EXPECT_EQ(s.run.cores, 2);
  EXPECT_DOUBLE_EQ(s.run.clock_ticks_per_s, 100.0);
  EXPECT_DOUBLE_EQ(s.run.max_p99_ms, 5.0);
  EXPECT_EQ(s.run.build, "/work/build");
  EXPECT_EQ(s.run.log, "/work/logs/refloc.0");
  EXPECT_EQ(s.run.load_average_before, "0.52 0.48 0.40");
  ASSERT_EQ(s.processes.size(), 2u);
  EXPECT_EQ(s.processes[0].program, "robot_sim");
  EXPECT_EQ(s.processes[0].cpu_ticks, 12345);
  EXPECT_EQ(s.processes[0].samples, 121);
  EXPECT_EQ(s.processes[0].rss_sum_kb, 2478080);
  EXPECT_EQ(s.processes[0].rss_end_kb, 20480);
  EXPECT_EQ(s.processes[0].rss_peak_kb, 22528);
  EXPECT_EQ(s.processes[1].program, "lcm-logger");
  EXPECT_EQ(s.processes[1].pid_restarts, 1);
}

TEST(LoadTestSamples, MalformedRecordsNameFileLineAndRecord) {
  const std::string head = "duration_s 20\nmeasured_s 20.1\n";
  EXPECT_THAT(error_of(head + "process pose_solver 1 2 3 4 5\n"),
              HasSubstr("samples.txt:3: process pose_solver: missing pid_restarts"));
  EXPECT_THAT(error_of(head + "process pose_solver 1 2 x 4 5 6\n"),
              HasSubstr("samples.txt:3: process pose_solver rss_sum_kb: expected a number, got 'x'"));
  EXPECT_THAT(error_of(head + "process pose_solver 1 2 3 4 5 6 7\n"), HasSubstr("unexpected '7'"));
  EXPECT_THAT(error_of(head + "process a 1 2 3 4 5 -1\n"), HasSubstr("whole number >= 0, got '-1'"));
  EXPECT_THAT(error_of("duration_s twenty\n"), HasSubstr("samples.txt:1: duration_s: expected a number"));
  EXPECT_THAT(error_of(head + "durations 20\n"), HasSubstr("samples.txt:3: unknown record 'durations'"));
  EXPECT_THAT(error_of(head + "cores\n"), HasSubstr("samples.txt:3: cores: missing value"));
}

TEST(LoadTestSamples, DurationsAndAProcessAreRequired) {
  EXPECT_THAT(error_of("measured_s 1\nprocess a 1 1 1 1 1 0\n"), HasSubstr("samples.txt: no duration_s"));
  EXPECT_THAT(error_of("duration_s 1\nprocess a 1 1 1 1 1 0\n"), HasSubstr("samples.txt: no measured_s"));
  EXPECT_THAT(error_of("duration_s 1\nmeasured_s 1\n"), HasSubstr("samples.txt: no process record"));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
