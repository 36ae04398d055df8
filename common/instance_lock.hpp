#pragma once
// One instance of a service per host and LCM bus. Two drivers fight over one
// sensor and two pose publishers interleave their POSE; a second process of the
// same service therefore refuses to start and names the one that runs.
//
// The lock is a listening unix socket bound to an abstract name
// ("\0refloc/<service>/<bus>"): the kernel releases it when the holder dies,
// even by kill -9 (no stale lock file), and abstract names are per network
// namespace, so parallel tests in their own namespaces never collide while two
// processes on one host (one namespace) always do. No LCM in here.

#include "common/json_config.hpp"

#include <string>

namespace refloc {

/// Thrown when another process holds the lock; a ConfigError so that main exits 2
/// (restarting cannot fix it: systemd's RestartPreventExitStatus=2, supervisord's exitcodes=2).
class InstanceConflictError : public ConfigError {
 public:
  using ConfigError::ConfigError;
};

/// What identifies "the same bus" in an LCM URL: the udpm group and port without the
/// options ("udpm://239.255.76.67:7667?ttl=1" -> "udpm://239.255.76.67:7667"; ttl only
/// says how far the traffic reaches). "" for buses private to one process or file
/// (memq://, file://): nothing to lock there.
std::string lcm_bus_identity(const std::string& lcm_url);

/// The abstract socket name (without its leading NUL) for service on bus; cut to fit sun_path.
std::string instance_lock_name(const std::string& service, const std::string& bus_identity);

class InstanceLock {
 public:
  /// Take the lock of service on the bus of lcm_url (a no-op for memq:// and file://).
  /// Throws InstanceConflictError naming the running pid when another process holds it,
  /// std::runtime_error when the socket cannot be made at all.
  InstanceLock(const std::string& service, const std::string& lcm_url);
  ~InstanceLock();
  InstanceLock(const InstanceLock&) = delete;
  InstanceLock& operator=(const InstanceLock&) = delete;

  bool held() const { return fd_ >= 0; }
  /// Close the connections refused starters left in the listen queue (each one asked
  /// for our pid), so that later starters still get it. Call now and then (1 Hz).
  void drain_refused_starters();

 private:
  int fd_ = -1;
};

}  // namespace refloc
