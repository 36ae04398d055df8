#include "service_instances.hpp"

#include <algorithm>

namespace refloc {
namespace {

// heartbeat_t::STATE_STOPPING and STATE_ERROR (lcmtypes/heartbeat_t.lcm; heartbeat_table_test checks the
// names).
constexpr int8_t kStateStopping = 4;
constexpr int8_t kStateError = 3;

}  // namespace

void ServiceInstances::update(const HeartbeatSample& heartbeat, double receive_time_s) {
  detector_.observe({heartbeat.service, heartbeat.pid, heartbeat.utime - heartbeat.uptime_us,
                     heartbeat.state == kStateStopping},
                    receive_time_s);
  last_by_pid_[{heartbeat.service, heartbeat.pid}] = {heartbeat, receive_time_s};
  // Forget processes long gone, so a long-running refloc-status does not grow with restarts.
  for (auto it = last_by_pid_.begin(); it != last_by_pid_.end();) {
    const bool gone =
        receive_time_s - it->second.received_s > 10 * DuplicateInstanceDetector::kDefaultWindowS;
    it = gone ? last_by_pid_.erase(it) : std::next(it);
  }
}

void ServiceInstances::split_duplicates(std::vector<ServiceStatus>& rows, double now_s) const {
  std::vector<ServiceStatus> out;
  out.reserve(rows.size());
  for (const auto& row : rows) {
    const auto instances = row.seen ? detector_.duplicates(row.service, now_s) : std::vector<HeardInstance>{};
    if (instances.size() < 2) {
      out.push_back(row);
      continue;
    }
    const std::string reason = describe_duplicates(instances);
    for (const auto& instance : instances) {
      ServiceStatus split = row;
      const auto last = last_by_pid_.find({row.service, instance.pid});
      if (last != last_by_pid_.end()) {
        split.last = last->second.heartbeat;
        split.age_s = std::max(0.0, now_s - last->second.received_s);
      }
      const std::string own = split.last.state_detail;
      // The service itself may say so already (ServiceRuntime hears its name from another pid).
      const bool says_so = own.find(" instances: pid ") != std::string::npos;
      split.last.state = kStateError;
      split.last.state_detail = says_so ? own : reason + (own.empty() ? "" : "; " + own);
      split.rate_in_hz = split.rate_out_hz = -1.0;  // the one rate of the name mixes both processes
      split.pid_changes = 0;                        // and so do its "restarts"
      split.duplicate = true;
      out.push_back(std::move(split));
    }
  }
  rows = std::move(out);
}

}  // namespace refloc
