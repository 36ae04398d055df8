#include "common/instance_lock.hpp"

#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <stdexcept>

namespace refloc {
namespace {

// LCM's own default group when a udpm URL names none.
constexpr const char* kDefaultUdpmGroup = "239.255.76.67:7667";
// Refused starters queue here until drain_refused_starters(); a full queue only costs
// the next starter the pid in its message, never the refusal itself.
constexpr int kListenBacklog = 64;

sockaddr_un abstract_address(const std::string& name, socklen_t& length) {
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  // sun_path[0] = '\0' makes it abstract; the name follows, not NUL-terminated.
  std::memcpy(address.sun_path + 1, name.data(), name.size());
  length = static_cast<socklen_t>(offsetof(sockaddr_un, sun_path) + 1 + name.size());
  return address;
}

/// The pid of the process listening on address, or 0 when it cannot be learnt.
pid_t holder_pid(const sockaddr_un& address, socklen_t length) {
  const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd < 0) return 0;
  pid_t pid = 0;
  if (connect(fd, reinterpret_cast<const sockaddr*>(&address), length) == 0) {
    ucred credentials{};
    socklen_t size = sizeof credentials;
    if (getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &credentials, &size) == 0) pid = credentials.pid;
  }
  close(fd);
  return pid;
}

}  // namespace

std::string lcm_bus_identity(const std::string& lcm_url) {
  const std::string scheme = "udpm://";
  if (lcm_url.compare(0, scheme.size(), scheme) != 0) return "";
  std::string group = lcm_url.substr(scheme.size());
  group = group.substr(0, group.find('?'));
  return scheme + (group.empty() ? kDefaultUdpmGroup : group);
}

std::string instance_lock_name(const std::string& service, const std::string& bus_identity) {
  const std::string name = "refloc/" + service + "/" + bus_identity;
  constexpr size_t kMaxName = sizeof(sockaddr_un::sun_path) - 1;  // after the leading NUL
  return name.substr(0, kMaxName);
}

InstanceLock::InstanceLock(const std::string& service, const std::string& lcm_url) {
  const std::string bus = lcm_bus_identity(lcm_url);
  if (bus.empty()) return;
  socklen_t length = 0;
  const sockaddr_un address = abstract_address(instance_lock_name(service, bus), length);
  fd_ = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC | SOCK_NONBLOCK, 0);
  if (fd_ < 0) throw std::runtime_error(std::string("instance lock: socket: ") + std::strerror(errno));
  if (bind(fd_, reinterpret_cast<const sockaddr*>(&address), length) != 0) {
    const int bind_errno = errno;
    close(fd_);
    fd_ = -1;
    if (bind_errno != EADDRINUSE)
      throw std::runtime_error(std::string("instance lock: bind: ") + std::strerror(bind_errno));
    const pid_t pid = holder_pid(address, length);
    throw InstanceConflictError("another " + service + " is already running on this host and LCM bus " + bus +
                                (pid > 0 ? ": pid " + std::to_string(pid) : " (pid unknown)") +
                                "; not starting a second one");
  }
  if (listen(fd_, kListenBacklog) != 0) {
    const int listen_errno = errno;
    close(fd_);
    fd_ = -1;
    throw std::runtime_error(std::string("instance lock: listen: ") + std::strerror(listen_errno));
  }
}

InstanceLock::~InstanceLock() {
  if (fd_ >= 0) close(fd_);
}

void InstanceLock::drain_refused_starters() {
  if (fd_ < 0) return;
  for (int i = 0; i < kListenBacklog; ++i) {
    const int client = accept4(fd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (client < 0) return;  // EAGAIN: queue empty (the socket is non-blocking)
    close(client);
  }
}

}  // namespace refloc
