#include "lms100_driver/tcp_connection.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>

#include "common/clock.hpp"

namespace refloc {

namespace {

/// poll() on fd and wake_fd; returns kOk when fd has the event.
IoStatus wait_fd(int fd, short events, int timeout_ms, int wake_fd) {
  pollfd fds[2] = {{fd, events, 0}, {wake_fd, POLLIN, 0}};
  const nfds_t n = wake_fd >= 0 ? 2 : 1;
  for (;;) {
    const int r = ::poll(fds, n, timeout_ms);
    if (r < 0) {
      if (errno == EINTR) continue;  // a signal: the caller's loop checks its stop flag
      return IoStatus::kError;
    }
    if (r == 0) return IoStatus::kTimeout;
    if (n == 2 && (fds[1].revents & POLLIN)) return IoStatus::kStopped;
    if (fds[0].revents & (events | POLLERR | POLLHUP)) return IoStatus::kOk;
    return IoStatus::kError;
  }
}

int to_ms(double seconds) { return seconds <= 0 ? 0 : static_cast<int>(std::ceil(seconds * 1000.0)); }

}  // namespace

ParseResult TcpConnection::connect(const std::string& host, uint16_t port, double timeout_s, int wake_fd) {
  close();
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  if (::inet_pton(AF_INET, host.c_str(), &addr.sin_addr) != 1) {
    addrinfo hints{};
    hints.ai_family = AF_INET;
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* result = nullptr;
    const int rc = ::getaddrinfo(host.c_str(), nullptr, &hints, &result);
    if (rc != 0 || result == nullptr)
      return ParseResult::failure("cannot resolve '" + host + "': " + gai_strerror(rc));
    addr.sin_addr = reinterpret_cast<sockaddr_in*>(result->ai_addr)->sin_addr;
    ::freeaddrinfo(result);
  }
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
  if (fd_ < 0) return ParseResult::failure(std::string("socket: ") + std::strerror(errno));
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
  const std::string where = host + ":" + std::to_string(port);
  if (::connect(fd_, reinterpret_cast<const sockaddr*>(&addr), sizeof addr) != 0) {
    if (errno != EINPROGRESS) {
      const std::string why = std::strerror(errno);
      close();
      return ParseResult::failure("connect " + where + ": " + why);
    }
    const IoStatus s = wait_fd(fd_, POLLOUT, to_ms(timeout_s), wake_fd);
    if (s != IoStatus::kOk) {
      close();
      return ParseResult::failure("connect " + where +
                                  (s == IoStatus::kStopped ? ": stopped" : ": timed out"));
    }
    int error = 0;
    socklen_t len = sizeof error;
    if (::getsockopt(fd_, SOL_SOCKET, SO_ERROR, &error, &len) != 0 || error != 0) {
      close();
      return ParseResult::failure("connect " + where + ": " + std::strerror(error));
    }
  }
  return ParseResult::success();
}

IoStatus TcpConnection::send_all(const std::string& bytes, double timeout_s, int wake_fd) {
  if (fd_ < 0) return IoStatus::kClosed;
  const int64_t deadline = monotonic_us() + static_cast<int64_t>(timeout_s * 1e6);
  size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n > 0) {
      sent += static_cast<size_t>(n);
      continue;
    }
    if (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR) {
      last_error_ = std::strerror(errno);
      return errno == EPIPE || errno == ECONNRESET ? IoStatus::kClosed : IoStatus::kError;
    }
    const int64_t left_us = deadline - monotonic_us();
    if (left_us <= 0) return IoStatus::kTimeout;
    const IoStatus s = wait_fd(fd_, POLLOUT, static_cast<int>(left_us / 1000 + 1), wake_fd);
    if (s != IoStatus::kOk) return s;
  }
  return IoStatus::kOk;
}

IoStatus TcpConnection::receive(uint8_t* buffer, size_t capacity, int timeout_ms, int wake_fd,
                                size_t& received) {
  received = 0;
  if (fd_ < 0) return IoStatus::kClosed;
  const IoStatus s = wait_fd(fd_, POLLIN, timeout_ms, wake_fd);
  if (s != IoStatus::kOk) return s;
  for (;;) {
    const ssize_t n = ::recv(fd_, buffer, capacity, 0);
    if (n > 0) {
      received = static_cast<size_t>(n);
      return IoStatus::kOk;
    }
    if (n == 0) {
      last_error_ = "connection closed by the sensor";
      return IoStatus::kClosed;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return IoStatus::kTimeout;
    last_error_ = std::strerror(errno);
    return errno == ECONNRESET ? IoStatus::kClosed : IoStatus::kError;
  }
}

void TcpConnection::close() {
  if (fd_ >= 0) {
    ::close(fd_);
    fd_ = -1;
  }
}

}  // namespace refloc
