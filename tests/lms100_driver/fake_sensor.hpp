#pragma once
// Scripted CoLa-A servers for the session tests: FakeSensor answers from a function, one
// client at a time; ChattySensor answers like a healthy LMS100 with a scan before every
// reply. Built on the driver's own splitter and framing (these test the session, not them).

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

namespace refloc::test {

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

inline size_t open_fd_count() {
  size_t n = 0;
  if (DIR* d = ::opendir("/proc/self/fd")) {
    while (::readdir(d) != nullptr) ++n;
    ::closedir(d);
  }
  return n;
}

/// Replies like a healthy LMS100; every reply is preceded by a scan telegram, and
/// STlms reports 3, 4, 4, then 7. Its microsecond clock runs with the host's (a scan's
/// transmission is now), so each scan has its own sensor time, as on a real sensor.
struct ChattySensor {
  std::atomic<unsigned> counter{100};
  std::atomic<int> status_polls{0};
  std::string current_scan_config = "9C4 1 9C4 FFF92230 225510";  // 25 Hz: the driver must change it
  std::vector<std::string> operator()(const std::string& r) {
    const auto transmit_us = static_cast<unsigned>(now_utime());
    std::vector<std::string> out{
        test::make_scan_telegram({500, 600, 700}, {10, 20, 30}, 16, counter++, transmit_us - 2429)};
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

}  // namespace refloc::test
