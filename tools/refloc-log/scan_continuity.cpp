#include "scan_continuity.hpp"

#include <algorithm>

namespace refloc {

int64_t ScanContinuityReport::dropped() const {
  const int64_t unprocessed = stages.empty() ? 0 : stages.back().scans_missing;
  return std::max<int64_t>(0, missing - unlogged_but_processed) + unprocessed;
}

ScanContinuity::ScanContinuity(std::string scan_channel, std::vector<std::string> stages, double tail_grace_s,
                               size_t max_gaps)
    : scan_channel_(std::move(scan_channel)),
      stage_channels_(std::move(stages)),
      tail_grace_s_(tail_grace_s),
      max_gaps_(max_gaps),
      stage_scans_(stage_channels_.size()) {
  r_.scan_channel = scan_channel_;
  for (const auto& c : stage_channels_) r_.stages.push_back({c, 0, 0, 0});
}

int ScanContinuity::stage_of(const std::string& channel) const {
  const auto it = std::find(stage_channels_.begin(), stage_channels_.end(), channel);
  return it == stage_channels_.end() ? -1 : static_cast<int>(it - stage_channels_.begin());
}

void ScanContinuity::add_scan(int32_t scan_counter, int64_t scan_utime, int64_t log_utime) {
  if (r_.scans == 0) first_log_utime_ = log_utime;
  ++r_.scans;
  last_scan_log_utime_ = log_utime;
  scan_log_utime_.try_emplace(scan_utime, log_utime);

  // The wire counter is 16 bits: step by the shortest signed distance to the previous one.
  const auto counter16 = static_cast<int64_t>(static_cast<uint16_t>(scan_counter));
  int64_t counter = counter16;
  if (have_counter_) {
    int64_t delta = (counter16 - last_counter_) & 0xFFFF;
    if (delta >= 0x8000) delta -= 0x10000;
    counter = last_counter_ + delta;
    if (delta < 0) ++r_.out_of_order;
    if (delta > 1) {
      ++r_.gap_count;
      if (r_.gaps.size() < max_gaps_) {
        r_.gaps.push_back(
            {last_counter_, delta - 1, static_cast<double>(log_utime - first_log_utime_) * 1e-6});
      }
    }
  }
  have_counter_ = true;
  last_counter_ = counter;
  if (!counters_seen_.insert(counter).second) ++r_.duplicates;
}

void ScanContinuity::add_stage(size_t stage, int64_t scan_utime) {
  if (stage >= stage_scans_.size()) return;
  ++r_.stages[stage].messages;
  stage_scans_[stage].insert(scan_utime);
}

void ScanContinuity::add_event(int64_t log_utime) {
  last_event_log_utime_ = std::max(last_event_log_utime_, log_utime);
}

void ScanContinuity::add_heartbeat(const std::string& service, int32_t pid, int64_t messages_in,
                                   int64_t messages_out, int64_t decode_errors, double p50_us, double p99_us,
                                   const std::vector<std::string>& counter_names,
                                   const std::vector<int64_t>& counter_values) {
  auto [it, inserted] = services_.try_emplace(service);
  ServiceAccumulator& a = it->second;
  ServiceHealth& h = a.health;
  if (inserted) {
    h.service = service;
    a.in_base = messages_in;
    a.out_base = messages_out;
  } else if (pid != a.pid) {
    ++h.restarts;
    a.decode_errors_before_restart = h.decode_errors;
    // The new process counts from zero.
    a.in_banked = h.messages_in_logged;
    a.out_banked = h.messages_out_logged;
    a.in_base = 0;
    a.out_base = 0;
  }
  a.pid = pid;
  ++h.heartbeats;
  h.messages_in = messages_in;
  h.messages_out = messages_out;
  h.messages_in_logged = a.in_banked + messages_in - a.in_base;
  h.messages_out_logged = a.out_banked + messages_out - a.out_base;
  h.decode_errors = a.decode_errors_before_restart + decode_errors;
  h.last_p50_us = p50_us;
  h.last_p99_us = p99_us;
  h.max_p99_us = std::max(h.max_p99_us, p99_us);
  h.counters.clear();
  for (size_t i = 0; i < counter_names.size() && i < counter_values.size(); ++i) {
    h.counters[counter_names[i]] = counter_values[i];
  }
}

ScanContinuityReport ScanContinuity::report() const {
  ScanContinuityReport r = r_;
  if (!counters_seen_.empty()) {
    r.first_counter = *counters_seen_.begin();
    r.last_counter = *counters_seen_.rbegin();
    r.expected = r.last_counter - r.first_counter + 1;
    r.missing = r.expected - static_cast<int64_t>(counters_seen_.size());
  }
  r.duration_s = static_cast<double>(last_scan_log_utime_ - first_log_utime_) * 1e-6;
  r.rate_hz = r.scans > 1 && r.duration_s > 0.0 ? static_cast<double>(r.scans - 1) / r.duration_s : 0.0;
  const int64_t end = std::max(last_event_log_utime_, last_scan_log_utime_);
  const auto grace_us = static_cast<int64_t>(tail_grace_s_ * 1e6);
  for (size_t s = 0; s < stage_scans_.size(); ++s) {
    for (const auto& [scan_utime, log_utime] : scan_log_utime_) {
      if (stage_scans_[s].count(scan_utime) > 0) {
        ++r.stages[s].scans_reached;
      } else if (log_utime + grace_us <= end) {
        ++r.stages[s].scans_missing;
      }
    }
  }
  std::set<int64_t> downstream_only;
  for (const auto& scans : stage_scans_) {
    for (int64_t scan_utime : scans)
      if (scan_log_utime_.count(scan_utime) == 0) downstream_only.insert(scan_utime);
  }
  r.unlogged_but_processed = static_cast<int64_t>(downstream_only.size());
  for (const auto& [name, a] : services_) r.services.push_back(a.health);
  return r;
}

}  // namespace refloc
