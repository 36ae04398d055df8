// The service runtime's systemd notifications, checked against a fake
// NOTIFY_SOCKET: READY=1 when run() starts, WATCHDOG=1 at half of
// WATCHDOG_USEC while healthy, none while unhealthy, STOPPING=1 at exit.

#include "common/service_runtime.hpp"
#include "fake_notify_socket.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::FakeNotifySocket;

int count_of(const std::vector<std::string>& messages, const std::string& what) {
  int n = 0;
  for (const auto& m : messages) n += m == what ? 1 : 0;
  return n;
}

/// Run a memq runtime for run_s seconds under the fake systemd environment.
std::vector<std::string> run_under_fake_systemd(FakeNotifySocket& socket, const char* watchdog_usec,
                                                bool healthy, double run_s) {
  setenv("NOTIFY_SOCKET", socket.path().c_str(), 1);
  setenv("WATCHDOG_USEC", watchdog_usec, 1);
  unsetenv("WATCHDOG_PID");
  {
    ServiceRuntime runtime("watchdog_test", "memq://");
    runtime.set_watchdog_healthy(healthy);
    runtime.add_periodic(run_s, [&runtime] { runtime.request_stop(); });
    EXPECT_EQ(runtime.run(), 0);
  }
  unsetenv("NOTIFY_SOCKET");
  unsetenv("WATCHDOG_USEC");
  return socket.drain();
}

TEST(ServiceWatchdog, HealthyLoopSendsReadyWatchdogAtHalfIntervalAndStopping) {
  FakeNotifySocket socket;
  ASSERT_TRUE(socket.bound());
  // WatchdogSec=0.2 s -> a ping every 0.1 s; over 0.65 s that is 6..7 pings (plus the first at start).
  const auto messages = run_under_fake_systemd(socket, "200000", true, 0.65);
  ASSERT_GE(messages.size(), 3u);
  EXPECT_EQ(messages.front(), "READY=1");
  EXPECT_EQ(messages.back(), "STOPPING=1");
  const int pings = count_of(messages, "WATCHDOG=1");
  EXPECT_GE(pings, 5);
  EXPECT_LE(pings, 9);
}

TEST(ServiceWatchdog, UnhealthyServiceSendsNoWatchdogPings) {
  FakeNotifySocket socket;
  ASSERT_TRUE(socket.bound());
  const auto messages = run_under_fake_systemd(socket, "200000", false, 0.4);
  EXPECT_EQ(count_of(messages, "READY=1"), 1);
  EXPECT_EQ(count_of(messages, "WATCHDOG=1"), 0);
  EXPECT_EQ(count_of(messages, "STOPPING=1"), 1);
}

TEST(ServiceWatchdog, NoWatchdogRequestedMeansNoPings) {
  FakeNotifySocket socket;
  ASSERT_TRUE(socket.bound());
  const auto messages = run_under_fake_systemd(socket, "0", true, 0.3);
  EXPECT_EQ(count_of(messages, "WATCHDOG=1"), 0);
  EXPECT_EQ(count_of(messages, "READY=1"), 1);
}

TEST(ServiceWatchdog, WithoutSystemdRunIsUnaffected) {
  unsetenv("NOTIFY_SOCKET");
  unsetenv("WATCHDOG_USEC");
  ServiceRuntime runtime("watchdog_test", "memq://");
  runtime.add_periodic(0.1, [&runtime] { runtime.request_stop(); });
  EXPECT_EQ(runtime.run(), 0);
  EXPECT_TRUE(runtime.watchdog_healthy());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
