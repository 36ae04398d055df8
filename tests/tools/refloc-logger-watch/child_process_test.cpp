// refloc-logger-watch's child (tools/refloc-logger-watch/child_process): how it ended, restarts.

#include "child_process.hpp"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <chrono>
#include <thread>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// Poll until the child ended (generous bound: this is no timing test).
void wait_exit(ChildProcess& child) {
  for (int i = 0; i < 500 && child.poll(); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
}

TEST(ChildProcess, ExitIsDescribedWithTheLastStderrLine) {
  ChildProcess child(
      {"sh", "-c", "echo first >&2; echo 'Unable to write: No space left on device' >&2; exit 3"});
  ASSERT_TRUE(child.start());
  wait_exit(child);
  EXPECT_FALSE(child.running());
  EXPECT_EQ(child.last_exit(), "exit 3: Unable to write: No space left on device");
  EXPECT_EQ(child.exits(), 1);
}

TEST(ChildProcess, MissingProgramIsExit127) {
  ChildProcess child({"/nonexistent/lcm-logger"});
  ASSERT_TRUE(child.start());
  wait_exit(child);
  EXPECT_EQ(child.last_exit().rfind("exit 127", 0), 0u) << child.last_exit();
}

TEST(ChildProcess, StopEndsAChildThatRuns) {
  ChildProcess child({"sleep", "30"});
  ASSERT_TRUE(child.start());
  EXPECT_TRUE(child.poll());
  child.stop(2.0);
  EXPECT_FALSE(child.running());
}

TEST(ChildProcess, KeepRunningRestartsAfterADelayThatGrowsWhileItFailsAtOnce) {
  ChildProcess child({"sh", "-c", "exit 1"});
  child.keep_running(0.0);  // first start at once
  ASSERT_TRUE(child.running());
  wait_exit(child);
  child.keep_running(0.1);  // noticed: next start 2 s later (a quick failure doubles the 1 s)
  EXPECT_FALSE(child.running());
  child.keep_running(1.5);
  EXPECT_FALSE(child.running());
  child.keep_running(2.2);
  EXPECT_TRUE(child.running());
  wait_exit(child);
  child.keep_running(2.3);  // 4 s now
  child.keep_running(6.0);
  EXPECT_FALSE(child.running());
  child.keep_running(6.4);
  EXPECT_TRUE(child.running());
  wait_exit(child);
  EXPECT_EQ(child.exits(), 3);
}

TEST(DescribeWaitStatus, ExitCodesAndSignals) {
  EXPECT_EQ(describe_wait_status(2 << 8), "exit 2");
  EXPECT_EQ(describe_wait_status(SIGKILL), "killed by signal 9 (Killed)");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
