#pragma once
// The model behind refloc-status: the latest HEARTBEAT of every service, the
// message rates derived from successive heartbeats of the same process, the
// age of each, and which expected services are missing. No LCM in here.

#include "common/heartbeat_state_name.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

/// One heartbeat_t as plain data (main.cpp converts).
struct HeartbeatSample {
  std::string service;
  int32_t pid = 0;
  int8_t state = 0;  ///< heartbeat_t::STATE_*
  std::string state_detail;
  int64_t utime = 0;  ///< sender's clock [us]
  int64_t uptime_us = 0;
  int64_t messages_in = 0;
  int64_t messages_out = 0;
  int64_t decode_errors = 0;
  double processing_p50_us = 0.0;
  double processing_p99_us = 0.0;
  std::vector<std::pair<std::string, int64_t>> counters;  ///< the service's own fault counters
};

/// One line of the status table.
struct ServiceStatus {
  std::string service;
  bool expected = false;
  bool seen = false;   ///< at least one heartbeat received
  bool stale = false;  ///< seen, but the last heartbeat is older than the limit
  HeartbeatSample last;
  double age_s = 0.0;        ///< since the last heartbeat was received [s]
  double rate_in_hz = -1.0;  ///< messages_in per second; < 0 until two heartbeats of one process
  double rate_out_hz = -1.0;
  int pid_changes = 0;     ///< restarts observed (or two processes sharing a name)
  bool duplicate = false;  ///< one of two processes sending under this name (ServiceInstances)

  /// Expected and not alive: never heard, or heard too long ago.
  bool missing() const { return expected && (!seen || stale); }
  /// Heard recently, saying ERROR (heartbeat_t::STATE_ERROR), expected or not.
  bool in_error() const { return seen && !stale && last.state == 3; }
  bool has_rates() const { return rate_in_hz >= 0.0; }
};

class HeartbeatTable {
 public:
  /// max_age_s: a heartbeat older than this marks its service stale (services send 1 Hz).
  explicit HeartbeatTable(double max_age_s = 3.0, double min_rate_window_s = 0.5);

  /// Record a heartbeat received at receive_time_s (local monotonic clock [s]).
  void update(const HeartbeatSample& heartbeat, double receive_time_s);

  /// Expected services first (in the given order), then every other service by name.
  std::vector<ServiceStatus> rows(const std::vector<std::string>& expected, double now_s) const;

  double max_age_s() const { return max_age_s_; }
  size_t service_count() const { return entries_.size(); }

 private:
  struct Entry {
    HeartbeatSample last;
    double received_s = 0.0;
    HeartbeatSample rate_base;  ///< older heartbeat of the same process the rates are taken from
    double rate_base_received_s = 0.0;
    double rate_in_hz = -1.0;
    double rate_out_hz = -1.0;
    int pid_changes = 0;
  };
  ServiceStatus status_of(const std::string& service, const Entry* entry, bool expected, double now_s) const;

  double max_age_s_;
  double min_rate_window_s_;
  std::map<std::string, Entry> entries_;
};

/// Names of the expected services that are missing or stale.
std::vector<std::string> missing_services(const std::vector<ServiceStatus>& rows);

/// Names of the services heard saying ERROR (not counting a name that runs twice: that has its own line).
std::vector<std::string> services_in_error(const std::vector<ServiceStatus>& rows);

/// Process exit status of refloc-status: 1 (kExitRuntimeFailure) when an expected service is
/// missing or stale, any service is in ERROR, or a service runs twice; else 0.
int status_exit_code(const std::vector<ServiceStatus>& rows);

}  // namespace refloc
