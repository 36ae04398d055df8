#pragma once
// Scan-to-pose latency through the pipeline from a log: every stage's message
// carries the scan's reference utime (LMS100_SCAN -> REFLECTORS ->
// REFLECTOR_MATCHES -> LASER_POSE), so the log's receive times of the messages
// with the same utime give each stage's delay and the end-to-end latency.
// The services' own handler times (HEARTBEAT processing p50/p99) are kept too.

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace refloc {

struct LatencyStats {
  size_t count = 0;
  double p50_ms = 0.0;
  double p99_ms = 0.0;
  double max_ms = 0.0;
  double mean_ms = 0.0;
};

/// The service's last HEARTBEAT in the log.
struct ServiceProcessing {
  std::string service;
  double p50_us = 0.0;
  double p99_us = 0.0;
  int64_t messages_in = 0;
  int64_t messages_out = 0;
};

struct LatencyReport {
  std::vector<std::string> channels;          ///< the pipeline, first to last
  std::vector<size_t> reached;                ///< scans seen on each channel
  std::vector<LatencyStats> stages;           ///< channels[i] -> channels[i + 1]
  LatencyStats end_to_end;                    ///< channels.front() -> channels.back()
  std::vector<ServiceProcessing> processing;  ///< by service name
};

/// The four channels from scan to laser pose.
std::vector<std::string> default_pipeline_channels();

/// Percentiles etc. of durations given in microseconds.
LatencyStats latency_stats(std::vector<double> durations_us);

class PipelineLatency {
 public:
  explicit PipelineLatency(std::vector<std::string> channels = default_pipeline_channels());

  /// Index of the channel in the pipeline, or -1.
  int stage_of(const std::string& channel) const;
  /// A message of stage `stage` about scan `scan_utime` was logged at log_utime [us].
  /// Only the first one per scan and stage counts (a replayed duplicate does not).
  void add(size_t stage, int64_t scan_utime, int64_t log_utime);
  /// A channel that carries no scan utime but is the pipeline's real end (POSE: one per
  /// odometry message, published after the scan's REFLECTOR_MATCHES reached pose_fusion): its
  /// first message logged at or after a scan's last stage ends that scan, as "<channel> (next)".
  void set_next_channel(std::string channel) { next_channel_ = std::move(channel); }
  const std::string& next_channel() const { return next_channel_; }
  /// A message of the next channel logged at log_utime [us] (in log order).
  void add_next(int64_t log_utime) { next_log_utimes_.push_back(log_utime); }
  /// Remember a service's handler time percentiles (HEARTBEAT); the last one wins.
  void add_processing(const ServiceProcessing& processing);

  LatencyReport report() const;

 private:
  std::vector<std::string> channels_;
  std::map<int64_t, std::vector<int64_t>> log_utime_by_scan_;  ///< -1 = not seen on that stage
  std::map<std::string, ServiceProcessing> processing_;
  std::string next_channel_;
  std::vector<int64_t> next_log_utimes_;
};

}  // namespace refloc
