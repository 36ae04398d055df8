// What refloc-logger-watch reports for lcm-logger (tools/refloc-logger-watch/logger_health).

#include "logger_health.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int8_t kOk = 1;
constexpr int8_t kError = 3;
constexpr int64_t kMb = 1024 * 1024;

LoggerObservation healthy(double now_s, int64_t bytes, int64_t bus) {
  LoggerObservation o;
  o.now_s = now_s;
  o.logger_running = true;
  o.log_file_bytes = bytes;
  o.log_file_inode = 7;
  o.bus_messages = bus;
  o.free_bytes = 10'000 * kMb;
  return o;
}

TEST(LoggerHealth, RecordingLoggerIsOk) {
  LoggerHealth h({});
  for (int i = 0; i < 20; ++i) {
    const auto v = h.evaluate(healthy(i, 1000 + 100 * i, 50 * i));
    EXPECT_EQ(v.state, kOk) << v.detail;
    EXPECT_EQ(v.detail, "");
  }
}

TEST(LoggerHealth, FullDiskIsAnErrorNamingTheFreeSpaceAndTheDirectory) {
  LoggerHealth h({100 * kMb, 5.0, "logs/"});
  auto o = healthy(0, 1000, 0);
  o.free_bytes = 4096;
  const auto v = h.evaluate(o);
  EXPECT_EQ(v.state, kError);
  EXPECT_EQ(v.detail, "disk full: 0 MB free in logs/");
}

TEST(LoggerHealth, LowDiskIsAnErrorBeforeItIsFull) {
  LoggerHealth h({100 * kMb, 5.0, "logs/"});
  auto o = healthy(0, 1000, 0);
  o.free_bytes = 37 * kMb;
  EXPECT_EQ(h.evaluate(o).detail, "disk almost full: 37 MB free in logs/ (minimum 100 MB)");
  o.free_bytes = 100 * kMb;
  EXPECT_EQ(h.evaluate(o).state, kOk);
}

TEST(LoggerHealth, ExitedLoggerIsAnErrorWithHowItEnded) {
  LoggerHealth h({});
  auto o = healthy(0, 1000, 0);
  o.logger_running = false;
  o.last_exit = "exit 1: Unable to open log file: Permission denied";
  const auto v = h.evaluate(o);
  EXPECT_EQ(v.state, kError);
  EXPECT_EQ(v.detail, "lcm-logger exits: exit 1: Unable to open log file: Permission denied");
  o.last_exit.clear();
  EXPECT_EQ(h.evaluate(o).detail, "lcm-logger exits: not running");
}

TEST(LoggerHealth, BusyBusWithAnUnchangedLogIsAnErrorAfterTheStallTime) {
  LoggerHealth h({100 * kMb, 5.0, "logs/"});
  EXPECT_EQ(h.evaluate(healthy(0, 1000, 0)).state, kOk);
  for (int i = 1; i < 6; ++i) EXPECT_EQ(h.evaluate(healthy(i, 1000, 50 * i)).state, kOk) << i;
  const auto v = h.evaluate(healthy(6, 1000, 300));
  EXPECT_EQ(v.state, kError);
  EXPECT_EQ(v.detail, "log not growing: messages on the bus, the log file unchanged for 5 s");
  EXPECT_EQ(h.evaluate(healthy(7, 1200, 350)).state, kOk);  // it writes again
}

TEST(LoggerHealth, QuietBusWithAnUnchangedLogIsOk) {
  LoggerHealth h({100 * kMb, 5.0, "logs/"});
  for (int i = 0; i < 30; ++i) EXPECT_EQ(h.evaluate(healthy(i, 1000, 10)).state, kOk) << i;
  // One message after a long quiet spell: the logger has its stall time to write it.
  EXPECT_EQ(h.evaluate(healthy(30, 1000, 11)).state, kOk);
  EXPECT_EQ(h.evaluate(healthy(31, 1100, 11)).state, kOk);
}

TEST(LoggerHealth, RotationToANewSmallerFileCountsAsGrowth) {
  LoggerHealth h({100 * kMb, 5.0, "logs/"});
  EXPECT_EQ(h.evaluate(healthy(0, 100 * kMb, 0)).state, kOk);
  auto o = healthy(1, 100, 50);
  o.log_file_inode = 8;
  EXPECT_EQ(h.evaluate(o).state, kOk);
  for (int i = 2; i < 6; ++i) {
    o = healthy(i, 100 + i, 50 * i);
    o.log_file_inode = 8;
    EXPECT_EQ(h.evaluate(o).state, kOk) << i;
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
