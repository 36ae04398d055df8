#include "pipeline_latency.hpp"

#include "common/latency_window.hpp"

#include <algorithm>
#include <numeric>

namespace refloc {

std::vector<std::string> default_pipeline_channels() {
  return {"LMS100_SCAN", "REFLECTORS", "REFLECTOR_MATCHES", "LASER_POSE"};
}

LatencyStats latency_stats(std::vector<double> durations_us) {
  LatencyStats s;
  s.count = durations_us.size();
  if (durations_us.empty()) return s;
  LatencyWindow window(durations_us.size());
  for (double d : durations_us) window.add(d);
  s.p50_ms = window.percentile(0.50) * 1e-3;
  s.p99_ms = window.percentile(0.99) * 1e-3;
  s.max_ms = *std::max_element(durations_us.begin(), durations_us.end()) * 1e-3;
  s.mean_ms =
      std::accumulate(durations_us.begin(), durations_us.end(), 0.0) / static_cast<double>(s.count) * 1e-3;
  return s;
}

PipelineLatency::PipelineLatency(std::vector<std::string> channels) : channels_(std::move(channels)) {}

int PipelineLatency::stage_of(const std::string& channel) const {
  const auto it = std::find(channels_.begin(), channels_.end(), channel);
  return it == channels_.end() ? -1 : static_cast<int>(it - channels_.begin());
}

void PipelineLatency::add(size_t stage, int64_t scan_utime, int64_t log_utime) {
  if (stage >= channels_.size()) return;
  auto [it, inserted] = log_utime_by_scan_.try_emplace(scan_utime, channels_.size(), int64_t{-1});
  int64_t& slot = it->second[stage];
  if (slot < 0) slot = log_utime;
}

void PipelineLatency::add_processing(const ServiceProcessing& processing) {
  processing_[processing.service] = processing;
}

LatencyReport PipelineLatency::report() const {
  LatencyReport r;
  r.channels = channels_;
  auto by_scan = log_utime_by_scan_;
  if (!next_channel_.empty()) {
    r.channels.push_back(next_channel_ + " (next)");
    std::vector<int64_t> next = next_log_utimes_;
    std::sort(next.begin(), next.end());
    for (auto& [scan_utime, times] : by_scan) {
      const auto it =
          times.back() < 0 ? next.end() : std::lower_bound(next.begin(), next.end(), times.back());
      times.push_back(it == next.end() ? -1 : *it);
    }
  }
  const size_t n = r.channels.size();
  r.reached.assign(n, 0);
  std::vector<std::vector<double>> stage_us(n > 0 ? n - 1 : 0);
  std::vector<double> total_us;
  for (const auto& [scan_utime, times] : by_scan) {
    for (size_t i = 0; i < n; ++i) r.reached[i] += times[i] >= 0 ? 1 : 0;
    for (size_t i = 0; i + 1 < n; ++i) {
      if (times[i] >= 0 && times[i + 1] >= 0)
        stage_us[i].push_back(static_cast<double>(times[i + 1] - times[i]));
    }
    if (n >= 2 && times.front() >= 0 && times.back() >= 0) {
      total_us.push_back(static_cast<double>(times.back() - times.front()));
    }
  }
  for (auto& s : stage_us) r.stages.push_back(latency_stats(std::move(s)));
  r.end_to_end = latency_stats(std::move(total_us));
  for (const auto& [name, p] : processing_) r.processing.push_back(p);
  return r;
}

}  // namespace refloc
