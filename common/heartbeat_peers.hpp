#pragma once
// Two processes publishing under one service name, told apart from HEARTBEAT alone.
// A restart (old pid's last heartbeat, then a new pid) is not a duplicate; two
// processes that keep sending side by side are. No LCM in here: the runtime and
// refloc-status convert heartbeat_t at their edge.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace refloc {

/// Who sent a heartbeat. The message carries no host name; the process's start time
/// (utime - uptime_us, sender's clock) tells two processes with one pid on two hosts apart.
struct HeartbeatIdentity {
  std::string service;
  int32_t pid = 0;
  int64_t start_utime = 0;  ///< sender's wall clock minus its uptime [us]
  bool stopping = false;    ///< the sender's last heartbeat (heartbeat_t::STATE_STOPPING)
};

/// One process heard under a service name.
struct HeardInstance {
  int32_t pid = 0;
  int64_t start_utime = 0;
  double first_heard_s = 0.0;  ///< local receive clock [s]
  double last_heard_s = 0.0;
};

class DuplicateInstanceDetector {
 public:
  /// Heartbeats come at 1 Hz: an instance not heard for window_s [s] is gone.
  static constexpr double kDefaultWindowS = 3.0;
  /// Two heartbeats with one pid whose start times differ by more than this are two processes [us]
  /// (clock slew and the few microseconds between utime and uptime stay far below it).
  static constexpr int64_t kSameStartToleranceUs = 2'000'000;

  explicit DuplicateInstanceDetector(double window_s = kDefaultWindowS);

  /// Record one heartbeat received at now_s (local monotonic clock [s]).
  void observe(const HeartbeatIdentity& sender, double now_s);

  /// The instances of service alive at now_s whose heartbeats interleave with another's,
  /// in the order first heard; empty when the service runs once (or is restarting).
  std::vector<HeardInstance> duplicates(const std::string& service, double now_s) const;

  /// Every service name that has duplicates at now_s.
  std::vector<std::string> duplicated_services(double now_s) const;

 private:
  double window_s_;
  std::map<std::string, std::vector<HeardInstance>> instances_;
};

/// A service's own view: another process heard under its name (ServiceRuntime).
class OwnNameMonitor {
 public:
  OwnNameMonitor(std::string service, int32_t pid);
  /// A heartbeat heard on the bus; true when another process sent it under our name.
  bool observe(const HeartbeatIdentity& sender, double now_s);
  /// Our own heartbeat as we publish it (we count even where multicast loopback is off).
  void observe_own(int64_t start_utime, double now_s);
  /// "two instances: pid A, pid B" while another process keeps sending under our name, else "".
  std::string conflict(double now_s) const;

 private:
  std::string service_;
  int32_t pid_;
  int64_t own_start_utime_ = 0;
  DuplicateInstanceDetector detector_;
};

/// "two instances: pid 12, pid 34" ("3 instances: ..." for more); "" for fewer than two.
std::string describe_duplicates(const std::vector<HeardInstance>& instances);

}  // namespace refloc
