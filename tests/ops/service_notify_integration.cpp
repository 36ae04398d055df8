// A real service binary (lcm_echo_peer, built on the service runtime like
// every service) under a fake systemd: READY=1 at start, WATCHDOG=1 at half of
// WATCHDOG_USEC while it runs, STOPPING=1 on SIGTERM. Runs in a private netns.

#include "fake_notify_socket.hpp"
#include "tests/tools/child_process.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

namespace refloc {
namespace {

int count_of(const std::vector<std::string>& messages, const std::string& what) {
  int n = 0;
  for (const auto& m : messages) n += m == what ? 1 : 0;
  return n;
}

TEST(ServiceNotify, RealServiceSendsReadyWatchdogAndStopping) {
  testing::FakeNotifySocket socket;
  ASSERT_TRUE(socket.bound());
  setenv("NOTIFY_SOCKET", socket.path().c_str(), 1);
  setenv("WATCHDOG_USEC", "400000", 1);  // WatchdogSec=0.4 -> a ping every 0.2 s
  testing::ChildProcess peer(
      {std::string(REFLOC_BINARY_DIR) + "/bin/lcm_echo_peer", "--lcm-url", "udpm://239.255.76.67:7667?ttl=0"},
      "/dev/null");
  unsetenv("NOTIFY_SOCKET");
  unsetenv("WATCHDOG_USEC");
  ASSERT_GT(peer.pid(), 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const auto running = socket.drain();
  ASSERT_FALSE(running.empty());
  EXPECT_EQ(running.front(), "READY=1");
  const int pings = count_of(running, "WATCHDOG=1");
  EXPECT_GE(pings, 4);  // ~7 in 1.5 s minus start-up time
  EXPECT_LE(pings, 9);
  EXPECT_EQ(peer.stop(), 0);
  const auto stopping = socket.drain();
  EXPECT_EQ(count_of(stopping, "STOPPING=1"), 1);
}

}  // namespace
}  // namespace refloc
