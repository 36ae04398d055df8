#include "heartbeat_table.hpp"

#include "common/guarded_main.hpp"

#include <algorithm>
#include <set>

namespace refloc {

HeartbeatTable::HeartbeatTable(double max_age_s, double min_rate_window_s)
    : max_age_s_(max_age_s), min_rate_window_s_(min_rate_window_s) {}

void HeartbeatTable::update(const HeartbeatSample& heartbeat, double receive_time_s) {
  auto [it, inserted] = entries_.try_emplace(heartbeat.service);
  Entry& e = it->second;
  if (inserted) {
    e.rate_base = heartbeat;
    e.rate_base_received_s = receive_time_s;
  } else {
    const bool same_process = heartbeat.pid == e.last.pid &&
                              heartbeat.messages_in >= e.rate_base.messages_in &&
                              heartbeat.messages_out >= e.rate_base.messages_out;
    if (!same_process) {
      // Counters restarted from zero: no rate until the new process has sent two heartbeats.
      if (heartbeat.pid != e.last.pid) ++e.pid_changes;
      e.rate_base = heartbeat;
      e.rate_base_received_s = receive_time_s;
      e.rate_in_hz = e.rate_out_hz = -1.0;
    } else {
      // The sender's clock spaces its own counters best; receive times are the fallback
      // when that clock stepped backwards.
      double dt_s = static_cast<double>(heartbeat.utime - e.rate_base.utime) * 1e-6;
      if (dt_s <= 0.0) dt_s = receive_time_s - e.rate_base_received_s;
      // A short window (the extra heartbeat at shutdown) would give a noisy rate.
      if (dt_s >= min_rate_window_s_) {
        e.rate_in_hz = static_cast<double>(heartbeat.messages_in - e.rate_base.messages_in) / dt_s;
        e.rate_out_hz = static_cast<double>(heartbeat.messages_out - e.rate_base.messages_out) / dt_s;
        e.rate_base = heartbeat;
        e.rate_base_received_s = receive_time_s;
      }
    }
  }
  e.last = heartbeat;
  e.received_s = receive_time_s;
}

ServiceStatus HeartbeatTable::status_of(const std::string& service, const Entry* entry, bool expected,
                                        double now_s) const {
  ServiceStatus s;
  s.service = service;
  s.expected = expected;
  if (entry == nullptr) return s;
  s.seen = true;
  s.last = entry->last;
  s.age_s = std::max(0.0, now_s - entry->received_s);
  s.stale = s.age_s > max_age_s_;
  s.rate_in_hz = entry->rate_in_hz;
  s.rate_out_hz = entry->rate_out_hz;
  s.pid_changes = entry->pid_changes;
  return s;
}

std::vector<ServiceStatus> HeartbeatTable::rows(const std::vector<std::string>& expected,
                                                double now_s) const {
  std::vector<ServiceStatus> out;
  std::set<std::string> listed;
  for (const auto& name : expected) {
    if (!listed.insert(name).second) continue;
    const auto it = entries_.find(name);
    out.push_back(status_of(name, it == entries_.end() ? nullptr : &it->second, true, now_s));
  }
  for (const auto& [name, entry] : entries_) {
    if (listed.count(name) == 0) out.push_back(status_of(name, &entry, false, now_s));
  }
  return out;
}

std::vector<std::string> missing_services(const std::vector<ServiceStatus>& rows) {
  std::vector<std::string> names;
  for (const auto& r : rows) {
    if (r.missing()) names.push_back(r.service);
  }
  return names;
}

std::vector<std::string> services_in_error(const std::vector<ServiceStatus>& rows) {
  std::vector<std::string> names;
  for (const auto& r : rows) {
    if (r.in_error() && !r.duplicate) names.push_back(r.service);
  }
  return names;
}

int status_exit_code(const std::vector<ServiceStatus>& rows) {
  const bool duplicate =
      std::any_of(rows.begin(), rows.end(), [](const ServiceStatus& r) { return r.duplicate; });
  const bool healthy = missing_services(rows).empty() && services_in_error(rows).empty() && !duplicate;
  return healthy ? 0 : kExitRuntimeFailure;
}

}  // namespace refloc
