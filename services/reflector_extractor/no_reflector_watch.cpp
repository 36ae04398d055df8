#include "reflector_extractor/no_reflector_watch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

NoReflectorWatch::NoReflectorWatch(double timeout_s, double threshold_8bit)
    : timeout_us_(static_cast<int64_t>(std::llround(timeout_s * 1e6))), threshold_8bit_(threshold_8bit) {}

void NoReflectorWatch::restart(int64_t host_utime) {
  since_host_utime_ = host_utime;
  any_rssi_ = false;
  any_echo_ = false;
  max_rssi_8bit_ = 0.0;
  clusters_ = ExtractionStats{};
}

void NoReflectorWatch::observe(const BeamTable& table, const ExtractionStats& stats, size_t detections,
                               int64_t host_utime, std::vector<NodeEvent>& events) {
  if (!started_) {
    started_ = true;
    restart(host_utime);
  }
  last_host_utime_ = host_utime;
  if (detections > 0) {
    if (firing_) {
      events.push_back({nullptr, NodeEvent::Level::kInfo,
                        fmt::format("reflectors back after {:.1f} s without",
                                    static_cast<double>(host_utime - since_host_utime_) * 1e-6)});
    }
    firing_ = false;
    restart(host_utime);
    return;
  }
  any_rssi_ = any_rssi_ || table.has_rssi;
  for (const TableBeam& b : table.beams) {
    if (b.kind != BeamKind::kEcho) continue;
    any_echo_ = true;
    max_rssi_8bit_ = std::max(max_rssi_8bit_, b.rssi_8bit);
  }
  clusters_.clusters_considered += stats.clusters_considered;
  clusters_.rejected_too_few_beams += stats.rejected_too_few_beams;
  clusters_.rejected_too_wide += stats.rejected_too_wide;
  clusters_.rejected_too_narrow += stats.rejected_too_narrow;
  clusters_.rejected_not_round += stats.rejected_not_round;
  clusters_.rejected_radius += stats.rejected_radius;
  clusters_.rejected_occluded += stats.rejected_occluded;
  clusters_.rejected_fit_failed += stats.rejected_fit_failed;
  if (!firing_ && host_utime - since_host_utime_ > timeout_us_) {
    firing_ = true;
    events.push_back({"no_reflector_timeouts", NodeEvent::Level::kWarn, detail()});
  }
}

std::string NoReflectorWatch::detail() const {
  const std::string head = fmt::format("no reflector for {:.1f} s",
                                       static_cast<double>(last_host_utime_ - since_host_utime_) * 1e-6);
  if (!any_echo_) return head + ": no echo in the scans";
  if (!any_rssi_) return head + ": the scans carry no RSSI (energy screening impossible)";
  if (clusters_.clusters_considered == 0) {
    return fmt::format("{}: max RSSI {:.0f} (8-bit) < threshold {:.0f}", head, max_rssi_8bit_,
                       threshold_8bit_);
  }
  const ExtractionStats& c = clusters_;
  return fmt::format(
      "{}: {} bright clusters (max RSSI {:.0f} (8-bit), threshold {:.0f}) all rejected: too few beams {}, "
      "shape {}, occluded {}",
      head, c.clusters_considered, max_rssi_8bit_, threshold_8bit_, c.rejected_too_few_beams,
      c.rejected_too_wide + c.rejected_too_narrow + c.rejected_not_round + c.rejected_radius +
          c.rejected_fit_failed,
      c.rejected_occluded);
}

}  // namespace refloc
