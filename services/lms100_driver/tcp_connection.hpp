#pragma once
// A TCP client socket for the sensor link: non-blocking connect with a
// timeout, poll()-based send and receive that also wake up on a stop fd.
// The fd is owned: closed on close(), on a failed connect and in the destructor.

#include <cstddef>
#include <cstdint>
#include <string>

#include "lms100_driver/parse_result.hpp"

namespace refloc {

enum class IoStatus { kOk, kTimeout, kStopped, kClosed, kError };

class TcpConnection {
 public:
  TcpConnection() = default;
  ~TcpConnection() { close(); }
  TcpConnection(const TcpConnection&) = delete;
  TcpConnection& operator=(const TcpConnection&) = delete;

  /// Connects to host:port (IPv4 address or name) within timeout_s; wake_fd (or -1) aborts the wait.
  ParseResult connect(const std::string& host, uint16_t port, double timeout_s, int wake_fd);
  /// Sends all bytes before timeout_s.
  IoStatus send_all(const std::string& bytes, double timeout_s, int wake_fd);
  /// Waits up to timeout_ms for data and reads what is there into buffer; received = bytes read.
  IoStatus receive(uint8_t* buffer, size_t capacity, int timeout_ms, int wake_fd, size_t& received);
  void close();
  bool is_open() const { return fd_ >= 0; }
  /// The errno text of the last failure.
  const std::string& last_error() const { return last_error_; }

 private:
  int fd_ = -1;
  std::string last_error_;
};

}  // namespace refloc
