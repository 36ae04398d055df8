#pragma once
// refloc-status's view of a service that runs twice: every process heard under one
// name keeps its own last heartbeat, and while two of them send side by side
// (common/heartbeat_peers: a restart does not count) the service's one row becomes
// one ERROR row per process, "two instances: pid A, pid B". No LCM in here.

#include "common/heartbeat_peers.hpp"
#include "heartbeat_table.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

class ServiceInstances {
 public:
  /// Record a heartbeat received at receive_time_s (local monotonic clock [s]).
  void update(const HeartbeatSample& heartbeat, double receive_time_s);

  /// Replace the row of every service that runs more than once at now_s by one row per
  /// process: its own last heartbeat, state ERROR, the pids in the detail, duplicate set.
  void split_duplicates(std::vector<ServiceStatus>& rows, double now_s) const;

 private:
  struct Last {
    HeartbeatSample heartbeat;
    double received_s = 0.0;
  };
  DuplicateInstanceDetector detector_;
  std::map<std::pair<std::string, int32_t>, Last> last_by_pid_;
};

}  // namespace refloc
