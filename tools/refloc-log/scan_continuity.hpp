#pragma once
// Were scans dropped? From a log: the LMS100 scan counter of every LMS100_SCAN
// (consecutive on the sensor, uint16 on the wire) gives the scans that never
// reached the bus or the logger; matching the scan utime on the later stages
// (REFLECTORS, LASER_POSE) gives the scans a service did not turn into output.
// HEARTBEAT adds each service's own view: messages in/out, decode errors,
// handler time (the worst p99 of any window, not only the last), restarts.

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace refloc {

/// A run of scan counters that never appeared on the scan channel.
struct ScanCounterGap {
  int64_t after_counter = 0;  ///< last counter seen before the gap (unwrapped)
  int64_t missing = 0;        ///< counters skipped
  double at_s = 0.0;          ///< log time of the scan that ended the gap, from the first scan [s]
};

/// How many scans made it to one later channel.
struct StageCoverage {
  std::string channel;
  int64_t messages = 0;       ///< messages on the channel
  int64_t scans_reached = 0;  ///< scans (by utime) with at least one message on it
  /// Scans without a message on it, not counting the last tail_grace_s of the log
  /// (their output may simply not have been logged before the logger stopped).
  int64_t scans_missing = 0;
};

/// One service as its HEARTBEATs in the log describe it.
struct ServiceHealth {
  std::string service;
  int64_t heartbeats = 0;
  int64_t restarts = 0;     ///< pid changes
  int64_t messages_in = 0;  ///< last heartbeat (since the process started)
  int64_t messages_out = 0;
  /// Between its first and last heartbeat in the log (summed over restarts): set
  /// against the logged message counts, tells a service's drop from the logger's.
  int64_t messages_in_logged = 0;
  int64_t messages_out_logged = 0;
  int64_t decode_errors = 0;  ///< summed over restarts
  double last_p50_us = 0.0;
  double last_p99_us = 0.0;
  double max_p99_us = 0.0;                  ///< worst handler p99 of any heartbeat window [us]
  std::map<std::string, int64_t> counters;  ///< service-specific counters, last heartbeat
};

struct ScanContinuityReport {
  std::string scan_channel;
  int64_t scans = 0;                 ///< messages on the scan channel
  int64_t first_counter = 0;         ///< unwrapped
  int64_t last_counter = 0;          ///< unwrapped
  int64_t expected = 0;              ///< last_counter - first_counter + 1
  int64_t missing = 0;               ///< counters never seen between first and last
  int64_t duplicates = 0;            ///< scans whose counter was seen before
  int64_t out_of_order = 0;          ///< a counter behind the previous one (reordering or a sensor restart)
  double duration_s = 0.0;           ///< first to last scan, log time [s]
  double rate_hz = 0.0;              ///< (scans - 1) / duration_s
  std::vector<ScanCounterGap> gaps;  ///< at most max_gaps, in log order
  int64_t gap_count = 0;             ///< all of them
  /// Scans the log lacks on the scan channel but a later stage has (by utime):
  /// published, processed, only the logger missed them.
  int64_t unlogged_but_processed = 0;
  std::vector<StageCoverage> stages;
  std::vector<ServiceHealth> services;  ///< by name
  /// Scans lost anywhere: missing counters that no stage saw either, plus scans
  /// that never reached the last stage (within the grace rule).
  int64_t dropped() const;
};

class ScanContinuity {
 public:
  /// `stages`: later channels whose messages carry the scan's utime (e.g.
  /// REFLECTORS, LASER_POSE); `tail_grace_s`: see StageCoverage::scans_missing.
  ScanContinuity(std::string scan_channel, std::vector<std::string> stages, double tail_grace_s = 0.5,
                 size_t max_gaps = 20);

  const std::string& scan_channel() const { return scan_channel_; }
  /// Index of a stage channel, or -1.
  int stage_of(const std::string& channel) const;

  /// A scan with its sensor counter (uint16 on the wire) and reference utime, logged at log_utime.
  void add_scan(int32_t scan_counter, int64_t scan_utime, int64_t log_utime);
  /// A message on stage `stage` about the scan with reference time scan_utime.
  void add_stage(size_t stage, int64_t scan_utime);
  /// Any logged event (the end of the log decides the tail grace).
  void add_event(int64_t log_utime);
  /// One HEARTBEAT.
  void add_heartbeat(const std::string& service, int32_t pid, int64_t messages_in, int64_t messages_out,
                     int64_t decode_errors, double p50_us, double p99_us,
                     const std::vector<std::string>& counter_names,
                     const std::vector<int64_t>& counter_values);

  ScanContinuityReport report() const;

 private:
  struct ServiceAccumulator {
    ServiceHealth health;
    int32_t pid = 0;
    int64_t decode_errors_before_restart = 0;
    int64_t in_base = 0;  ///< messages_in at the first heartbeat of this process
    int64_t out_base = 0;
    int64_t in_banked = 0;  ///< counted by earlier processes of the service
    int64_t out_banked = 0;
  };

  std::string scan_channel_;
  std::vector<std::string> stage_channels_;
  double tail_grace_s_;
  size_t max_gaps_;

  ScanContinuityReport r_;
  bool have_counter_ = false;
  int64_t last_counter_ = 0;  ///< unwrapped
  int64_t first_log_utime_ = 0;
  int64_t last_scan_log_utime_ = 0;
  int64_t last_event_log_utime_ = 0;
  std::set<int64_t> counters_seen_;             ///< unwrapped
  std::map<int64_t, int64_t> scan_log_utime_;   ///< scan utime -> log utime
  std::vector<std::set<int64_t>> stage_scans_;  ///< scan utimes seen per stage
  std::map<std::string, ServiceAccumulator> services_;
};

}  // namespace refloc
