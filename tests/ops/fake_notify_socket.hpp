#pragma once
// A unix datagram socket standing in for systemd's NOTIFY_SOCKET in tests.

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <string>
#include <vector>

namespace refloc::testing {

/// A unix datagram socket standing in for systemd's notify socket.
class FakeNotifySocket {
 public:
  FakeNotifySocket() {
    path_ = "/tmp/refloc_notify_" + std::to_string(getpid()) + "_" + std::to_string(instance_++);
    ::unlink(path_.c_str());
    fd_ = ::socket(AF_UNIX, SOCK_DGRAM | SOCK_NONBLOCK, 0);
    sockaddr_un addr{};
    addr.sun_family = AF_UNIX;
    path_.copy(addr.sun_path, sizeof(addr.sun_path) - 1);
    bound_ = ::bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof(addr)) == 0;
  }
  ~FakeNotifySocket() {
    ::close(fd_);
    ::unlink(path_.c_str());
  }
  FakeNotifySocket(const FakeNotifySocket&) = delete;
  FakeNotifySocket& operator=(const FakeNotifySocket&) = delete;

  bool bound() const { return bound_; }
  const std::string& path() const { return path_; }
  /// Every datagram received so far, in order.
  std::vector<std::string> drain() {
    std::vector<std::string> messages;
    char buffer[512];
    for (;;) {
      const ssize_t n = ::recv(fd_, buffer, sizeof(buffer), 0);
      if (n < 0) break;
      messages.emplace_back(buffer, static_cast<size_t>(n));
    }
    return messages;
  }

 private:
  static inline int instance_ = 0;  // several sockets in one test process
  std::string path_;
  int fd_ = -1;
  bool bound_ = false;
};

}  // namespace refloc::testing
