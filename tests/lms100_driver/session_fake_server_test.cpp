// Session behaviour that the emulator does not script: scans interleaved with
// replies, sMA acknowledgements, slow readiness, refused connections.
#include <arpa/inet.h>
#include <dirent.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "common/clock.hpp"
#include "lms100_driver/cola_a_format.hpp"
#include "lms100_driver/cola_a_splitter.hpp"
#include "lms100_driver/lms100_session.hpp"
#include "telegram_fixtures.hpp"

namespace refloc {
namespace {

using namespace std::chrono_literals;

/// A one-client-at-a-time CoLa-A server whose replies come from a function.
class FakeSensor {
 public:
  using Responder = std::function<std::vector<std::string>(const std::string& request)>;

  explicit FakeSensor(Responder responder) : responder_(std::move(responder)) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    const int one = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    ::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    ::listen(listen_fd_, 4);
    socklen_t len = sizeof addr;
    ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &len);
    port_ = ntohs(addr.sin_port);
    thread_ = std::thread([this] { serve(); });
  }
  ~FakeSensor() {
    stop_ = true;
    thread_.join();
    ::close(listen_fd_);
  }
  uint16_t port() const { return port_; }
  std::vector<std::string> requests() {
    std::lock_guard<std::mutex> lock(mutex_);
    return requests_;
  }
  /// Frames pushed every period while a client is connected (the stream).
  void set_stream(std::function<std::vector<std::string>()> stream) {
    std::lock_guard<std::mutex> lock(mutex_);
    stream_ = std::move(stream);
  }

 private:
  void serve() {
    while (!stop_) {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 20) <= 0) continue;
      const int fd = ::accept(listen_fd_, nullptr, nullptr);
      if (fd < 0) continue;
      ColaASplitter splitter;
      std::string payload;
      uint8_t buf[4096];
      int64_t next_stream = monotonic_us();
      while (!stop_) {
        pollfd c{fd, POLLIN, 0};
        if (::poll(&c, 1, 5) > 0) {
          const ssize_t n = ::recv(fd, buf, sizeof buf, 0);
          if (n <= 0) break;
          splitter.feed(buf, static_cast<size_t>(n));
          while (splitter.next(payload)) {
            {
              std::lock_guard<std::mutex> lock(mutex_);
              requests_.push_back(payload);
            }
            std::string out;
            for (const auto& f : responder_(payload)) out += frame_cola_a(f);
            ::send(fd, out.data(), out.size(), MSG_NOSIGNAL);
          }
        }
        std::function<std::vector<std::string>()> stream;
        {
          std::lock_guard<std::mutex> lock(mutex_);
          stream = stream_;
        }
        if (stream && monotonic_us() >= next_stream) {
          next_stream += 20'000;
          std::string out;
          for (const auto& f : stream()) out += frame_cola_a(f);
          ::send(fd, out.data(), out.size(), MSG_NOSIGNAL);
        }
      }
      ::close(fd);
    }
  }

  Responder responder_;
  int listen_fd_ = -1;
  uint16_t port_ = 0;
  std::atomic<bool> stop_{false};
  std::thread thread_;
  std::mutex mutex_;
  std::vector<std::string> requests_;
  std::function<std::vector<std::string>()> stream_;
};

size_t open_fd_count() {
  size_t n = 0;
  if (DIR* d = ::opendir("/proc/self/fd")) {
    while (::readdir(d) != nullptr) ++n;
    ::closedir(d);
  }
  return n;
}

/// Replies like a healthy LMS100; every reply is preceded by a scan telegram, and
/// STlms reports 3, 4, 4, then 7.
struct ChattySensor {
  std::atomic<unsigned> counter{100};
  std::atomic<int> status_polls{0};
  std::string current_scan_config = "9C4 1 9C4 FFF92230 225510";  // 25 Hz: the driver must change it
  std::vector<std::string> operator()(const std::string& r) {
    std::vector<std::string> out{test::make_scan_telegram({500, 600, 700}, {10, 20, 30}, 16, counter++)};
    if (r.rfind("sMN SetAccessMode", 0) == 0) out.push_back("sAN SetAccessMode 1");
    if (r == "sRN LMPscancfg") out.push_back("sRA LMPscancfg " + current_scan_config);
    if (r.rfind("sMN mLMPsetscancfg", 0) == 0)
      out.push_back("sAN mLMPsetscancfg 0 1388 1 1388 FFF92230 225510");
    if (r.rfind("sWN LMDscandatacfg", 0) == 0) out.push_back("sWA LMDscandatacfg");
    if (r == "sMN LMCstartmeas") {
      out.push_back("sMA LMCstartmeas");
      out.push_back("sAN LMCstartmeas 0");
    }
    if (r == "sMN LMCstopmeas") out.push_back("sAN LMCstopmeas 0");
    if (r == "sMN Run") out.push_back("sAN Run 1");
    if (r == "sRN STlms") {
      static const char* kStates[] = {"3", "4", "4", "7"};
      const int k = std::min(status_polls++, 3);
      out.push_back(std::string("sRA STlms ") + kStates[k] + " 0 8 00:17:28 A 01.01.1970 0 0 0");
    }
    if (r.rfind("sEN LMDscandata", 0) == 0) out.push_back("sEA " + r.substr(4));
    return out;
  }
};

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

}  // namespace
}  // namespace refloc
