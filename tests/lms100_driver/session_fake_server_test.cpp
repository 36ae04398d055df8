// Session behaviour that the emulator does not script: scans interleaved with
// replies, sMA acknowledgements, slow readiness, refused connections.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "common/clock.hpp"
#include "fake_sensor.hpp"
#include "lms100_driver/lms100_session.hpp"
#include "telegram_fixtures.hpp"

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using namespace std::chrono_literals;
using test::ChattySensor;
using test::FakeSensor;
using test::open_fd_count;

Lms100SessionConfig local_config(uint16_t port) {
  Lms100SessionConfig c;
  c.host = "127.0.0.1";
  c.port = port;
  c.reply_timeout_s = 0.5;
  c.status_poll_period_s = 0.05;
  return c;
}

TEST(SessionFakeServer, ScansInterleavedWithRepliesGoToTheScanPathAndSetupCompletes) {
  ChattySensor chatty;
  FakeSensor sensor([&](const std::string& r) { return chatty(r); });
  std::atomic<int> scans{0};
  std::vector<SessionState> states;
  std::mutex states_mutex;
  Lms100Session session(
      local_config(sensor.port()), [&](const LaserScan&) { ++scans; },
      [&](SessionState s, const std::string&) {
        std::lock_guard<std::mutex> lock(states_mutex);
        states.push_back(s);
      });
  session.start_thread();
  const int64_t deadline = monotonic_us() + 3'000'000;
  while (session.state() != SessionState::kStreaming && monotonic_us() < deadline)
    std::this_thread::sleep_for(5ms);
  ASSERT_EQ(session.state(), SessionState::kStreaming);
  // Every reply came with a scan, so scans arrived before streaming was even asked for.
  EXPECT_GE(scans.load(), 10);
  EXPECT_EQ(chatty.status_polls.load(), 4);
  session.join();
  const auto requests = sensor.requests();
  const std::vector<std::string> expected_start = {"sEN LMDscandata 0",
                                                   "sMN SetAccessMode 03 F4724744",
                                                   "sRN LMPscancfg",
                                                   "sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000",
                                                   "sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1",
                                                   "sMN LMCstartmeas",
                                                   "sMN Run",
                                                   "sRN STlms"};
  ASSERT_GE(requests.size(), expected_start.size());
  for (size_t i = 0; i < expected_start.size(); ++i) EXPECT_EQ(requests[i], expected_start[i]);
  // Stop: stream off, login, stop measurement.
  ASSERT_GE(requests.size(), 3u);
  EXPECT_EQ(requests[requests.size() - 3], "sEN LMDscandata 0");
  EXPECT_EQ(requests[requests.size() - 2], "sMN SetAccessMode 03 F4724744");
  EXPECT_EQ(requests[requests.size() - 1], "sMN LMCstopmeas");
  EXPECT_EQ(session.counters().sfa_errors.load(), 0u);
  EXPECT_EQ(session.counters().reconnects.load(), 0u);
  std::lock_guard<std::mutex> lock(states_mutex);
  EXPECT_NE(std::find(states.begin(), states.end(), SessionState::kWaitingReady), states.end());
}

TEST(SessionFakeServer, ScanConfigIsNotRewrittenWhenTheSensorAlreadyScansThatWay) {
  ChattySensor chatty;
  chatty.current_scan_config = "1388 1 1388 FFF92230 225510";
  FakeSensor sensor([&](const std::string& r) { return chatty(r); });
  Lms100Session session(local_config(sensor.port()), [](const LaserScan&) {});
  session.start_thread();
  const int64_t deadline = monotonic_us() + 3'000'000;
  while (session.state() != SessionState::kStreaming && monotonic_us() < deadline)
    std::this_thread::sleep_for(5ms);
  ASSERT_EQ(session.state(), SessionState::kStreaming);
  session.join();
  const auto requests = sensor.requests();
  EXPECT_EQ(std::count_if(requests.begin(), requests.end(),
                          [](const std::string& r) { return r.rfind("sMN mLMPsetscancfg", 0) == 0; }),
            0);
  EXPECT_EQ(std::count(requests.begin(), requests.end(), std::string("sRN LMPscancfg")), 1);
}

TEST(SessionFakeServer, SensorNeverReadyTimesOutAndReconnects) {
  FakeSensor sensor([](const std::string& r) -> std::vector<std::string> {
    if (r == "sRN STlms") return {"sRA STlms 3 0 8 00:17:28 A 01.01.1970 0 0 0"};
    ChattySensor healthy;
    auto out = healthy(r);
    out.erase(out.begin());  // no scans
    return out;
  });
  Lms100SessionConfig c = local_config(sensor.port());
  c.ready_timeout_s = 0.3;
  c.backoff_initial_s = 0.05;
  Lms100Session session(c, [](const LaserScan&) {});
  session.start_thread();
  const int64_t deadline = monotonic_us() + 3'000'000;
  while (session.counters().reconnects.load() < 2 && monotonic_us() < deadline)
    std::this_thread::sleep_for(10ms);
  session.join();
  EXPECT_GE(session.counters().reconnects.load(), 2u);
  EXPECT_GE(session.counters().timeouts.load(), 2u);
  EXPECT_EQ(session.counters().scans.load(), 0u);
}

TEST(SessionFakeServer, LoginRefusedBySfaIsCountedAndRetriedWithBackoff) {
  FakeSensor sensor([](const std::string& r) -> std::vector<std::string> {
    if (r.rfind("sMN SetAccessMode", 0) == 0) return {"sFA A"};
    if (r.rfind("sEN", 0) == 0) return {"sEA LMDscandata 0"};
    return {};
  });
  Lms100Session session(local_config(sensor.port()), [](const LaserScan&) {});
  session.start_thread();
  std::this_thread::sleep_for(1200ms);  // attempts at 0, 0.5 s (+0.5), 1.5 s (+1.0)
  session.join();
  EXPECT_EQ(session.counters().sfa_errors.load(), 2u);
  EXPECT_EQ(session.counters().connects.load(), 2u);
}

TEST(SessionFakeServer, RefusedConnectionsBackOffAndLeakNoDescriptors) {
  // A port nobody listens on: bind one, note it, close it.
  const int probe = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ::bind(probe, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
  socklen_t len = sizeof addr;
  ::getsockname(probe, reinterpret_cast<sockaddr*>(&addr), &len);
  ::close(probe);

  Lms100SessionConfig c = local_config(ntohs(addr.sin_port));
  c.backoff_initial_s = 0.01;
  c.backoff_max_s = 0.02;
  Lms100Session session(c, [](const LaserScan&) {});
  const size_t fds_before = open_fd_count();
  session.start_thread();
  std::this_thread::sleep_for(600ms);
  const size_t fds_during = open_fd_count();
  const uint64_t failures = session.counters().connect_failures.load();
  session.join();
  EXPECT_GE(failures, 15u);
  EXPECT_LE(failures, 70u);  // backed off, not a busy loop
  EXPECT_LE(fds_during, fds_before + 1);
  EXPECT_EQ(open_fd_count(), fds_before);
}

TEST(SessionFakeServer, StopDuringLongBackoffReturnsAtOnce) {
  Lms100SessionConfig c = local_config(1);
  c.backoff_initial_s = 30;
  c.backoff_max_s = 30;
  Lms100Session session(c, [](const LaserScan&) {});
  session.start_thread();
  std::this_thread::sleep_for(100ms);
  const int64_t t0 = monotonic_us();
  session.join();
  EXPECT_LT(monotonic_us() - t0, 200'000);
  EXPECT_EQ(session.state(), SessionState::kStopped);
}

TEST(SessionFakeServer, StreakOfBadScansReconnects) {
  ChattySensor chatty;
  FakeSensor sensor([&](const std::string& r) {
    auto out = chatty(r);
    out.erase(out.begin());
    return out;
  });
  sensor.set_stream([] { return std::vector<std::string>{"sSN LMDscandata 1 1 ZZ"}; });
  Lms100SessionConfig c = local_config(sensor.port());
  c.max_parse_error_streak = 3;
  Lms100Session session(c, [](const LaserScan&) {});
  session.start_thread();
  const int64_t deadline = monotonic_us() + 3'000'000;
  while (session.counters().reconnects.load() < 1 && monotonic_us() < deadline)
    std::this_thread::sleep_for(10ms);
  session.join();
  EXPECT_GE(session.counters().reconnects.load(), 1u);
  EXPECT_GE(session.counters().parse_errors.load(), 3u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
