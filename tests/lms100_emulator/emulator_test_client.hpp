#pragma once
// A minimal CoLa-A client for the emulator tests: real loopback TCP, frames split
// by the driver's ColaASplitter, every raw read kept so tests can see how the bytes
// were cut into writes.

#include "common/clock.hpp"
#include "lms100_driver/cola_a_splitter.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace refloc::test {

struct ReceivedFrame {
  std::string payload;
  int64_t receive_mono_us = 0;
};

class EmulatorTestClient {
 public:
  explicit EmulatorTestClient(uint16_t port) {
    fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(port);
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    connected_ = ::connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
  }
  ~EmulatorTestClient() {
    if (fd_ >= 0) ::close(fd_);
  }
  EmulatorTestClient(const EmulatorTestClient&) = delete;
  EmulatorTestClient& operator=(const EmulatorTestClient&) = delete;

  bool connected() const { return connected_; }
  bool closed_by_peer() const { return closed_; }

  void send_raw(const std::string& bytes) { (void)::send(fd_, bytes.data(), bytes.size(), MSG_NOSIGNAL); }
  void send_request(const std::string& payload) { send_raw("\x02" + payload + "\x03"); }

  /// Next frame of any kind within timeout_ms; false on timeout or when the peer closed.
  bool next_frame(ReceivedFrame& frame, int timeout_ms) {
    const int64_t deadline = monotonic_us() + int64_t{timeout_ms} * 1000;
    while (frames_.empty()) {
      const int64_t left_ms = (deadline - monotonic_us()) / 1000;
      if (left_ms < 0 || closed_ || !read_once(static_cast<int>(left_ms))) return false;
    }
    frame = std::move(frames_.front());
    frames_.pop_front();
    return true;
  }

  /// Sends a request and returns the first frame that is not a stream scan.
  std::string request(const std::string& payload, int timeout_ms = 1000) {
    send_request(payload);
    return next_reply(timeout_ms);
  }
  /// The next frame that is not an "sSN LMDscandata" event; "" on timeout.
  std::string next_reply(int timeout_ms = 1000) {
    ReceivedFrame frame;
    while (next_frame(frame, timeout_ms)) {
      if (frame.payload.rfind("sSN LMDscandata", 0) != 0) return frame.payload;
    }
    return {};
  }
  /// The next stream scan within timeout_ms; false on timeout.
  bool next_scan(ReceivedFrame& scan, int timeout_ms) {
    while (next_frame(scan, timeout_ms)) {
      if (scan.payload.rfind("sSN LMDscandata", 0) == 0) return true;
    }
    return false;
  }
  /// Reads until the peer closes or timeout_ms pass; true if it closed.
  bool wait_for_close(int timeout_ms) {
    const int64_t deadline = monotonic_us() + int64_t{timeout_ms} * 1000;
    while (!closed_) {
      const int64_t left_ms = (deadline - monotonic_us()) / 1000;
      if (left_ms < 0) return false;
      read_once(static_cast<int>(left_ms));
    }
    return true;
  }

  const std::vector<std::string>& raw_reads() const { return raw_reads_; }
  const ColaASplitter& splitter() const { return splitter_; }

 private:
  bool read_once(int timeout_ms) {
    pollfd p{fd_, POLLIN, 0};
    if (::poll(&p, 1, timeout_ms) <= 0) return false;
    char buffer[65536];
    const ssize_t n = ::recv(fd_, buffer, sizeof(buffer), 0);
    if (n <= 0) {
      closed_ = true;
      return false;
    }
    const int64_t now = monotonic_us();
    raw_reads_.emplace_back(buffer, static_cast<size_t>(n));
    splitter_.feed(reinterpret_cast<const uint8_t*>(buffer), static_cast<size_t>(n));
    std::string payload;
    while (splitter_.next(payload)) frames_.push_back({payload, now});
    return true;
  }

  int fd_ = -1;
  bool connected_ = false;
  bool closed_ = false;
  ColaASplitter splitter_;
  std::deque<ReceivedFrame> frames_;
  std::vector<std::string> raw_reads_;
};

}  // namespace refloc::test
