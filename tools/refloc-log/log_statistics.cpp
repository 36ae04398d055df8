#include "log_statistics.hpp"

#include <algorithm>

namespace refloc {

LogStatistics::LogStatistics(double gap_threshold_s, size_t max_gaps, double heartbeat_silence_s)
    : threshold_s_(gap_threshold_s), max_gaps_(max_gaps), heartbeat_silence_s_(heartbeat_silence_s) {}

void LogStatistics::add_gap(LogGap gap) {
  if (gaps_.size() < max_gaps_) {
    gaps_.push_back(std::move(gap));
  } else {
    ++gaps_not_listed_;
  }
}

void LogStatistics::add_heartbeat(const std::string& channel, const std::string& service, int64_t log_utime,
                                  int64_t eventnum) {
  auto [it, inserted] = last_heartbeat_utime_.try_emplace(service, log_utime);
  if (!inserted) {
    const double gap_s = static_cast<double>(log_utime - it->second) * 1e-6;
    if (gap_s > std::max(threshold_s_, heartbeat_silence_s_)) {
      add_gap({channel + "(" + service + ")", static_cast<double>(it->second - first_utime_) * 1e-6, gap_s,
               eventnum});
    }
    it->second = log_utime;
  }
}

void LogStatistics::add(const std::string& channel, int64_t log_utime, size_t bytes, int64_t eventnum,
                        const char* type) {
  if (events_ == 0) {
    first_utime_ = log_utime;
  } else if (log_utime - last_utime_ > largest_gap_us_) {
    largest_gap_us_ = log_utime - last_utime_;
    largest_gap_start_us_ = last_utime_;
  }
  ++events_;
  last_utime_ = std::max(last_utime_, log_utime);

  auto [it, inserted] = channels_.try_emplace(channel);
  Accumulator& a = it->second;
  if (inserted) {
    a.s.channel = channel;
    a.s.type = type ? type : "?";
    a.s.first_utime = log_utime;
  } else {
    const int64_t gap_us = log_utime - a.s.last_utime;
    if (gap_us > a.largest_gap_us) {
      a.largest_gap_us = gap_us;
      a.largest_gap_start_us = a.s.last_utime;
      a.s.largest_gap_event = eventnum;
    }
    // Heartbeat gaps are judged per service (add_heartbeat).
    if (static_cast<double>(gap_us) * 1e-6 > threshold_s_ && a.s.type != "heartbeat_t") {
      add_gap({channel, static_cast<double>(a.s.last_utime - first_utime_) * 1e-6,
               static_cast<double>(gap_us) * 1e-6, eventnum});
    }
  }
  ++a.s.count;
  a.s.bytes += static_cast<int64_t>(bytes);
  a.s.last_utime = log_utime;
}

LogSummary LogStatistics::summary() const {
  LogSummary out;
  out.events = events_;
  out.first_utime = first_utime_;
  out.last_utime = last_utime_;
  out.duration_s = static_cast<double>(last_utime_ - first_utime_) * 1e-6;
  out.largest_gap_s = static_cast<double>(largest_gap_us_) * 1e-6;
  out.largest_gap_at_s = static_cast<double>(largest_gap_start_us_ - first_utime_) * 1e-6;
  out.gap_threshold_s = threshold_s_;
  for (const auto& [name, a] : channels_) {
    ChannelSummary s = a.s;
    const double span_s = static_cast<double>(s.last_utime - s.first_utime) * 1e-6;
    s.rate_hz = s.count > 1 && span_s > 0.0 ? static_cast<double>(s.count - 1) / span_s : 0.0;
    if (a.largest_gap_us >= 0) {
      s.largest_gap_s = static_cast<double>(a.largest_gap_us) * 1e-6;
      s.largest_gap_at_s = static_cast<double>(a.largest_gap_start_us - first_utime_) * 1e-6;
    }
    out.channels.push_back(std::move(s));
  }
  out.gaps = gaps_;
  std::stable_sort(out.gaps.begin(), out.gaps.end(),
                   [](const LogGap& a, const LogGap& b) { return a.start_s < b.start_s; });
  out.gaps_not_listed = gaps_not_listed_;
  return out;
}

}  // namespace refloc
