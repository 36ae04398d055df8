#include "lms100_driver/link_health.hpp"

#include <fmt/format.h>

namespace refloc {

LinkVerdict judge_link(SessionState state, const std::string& detail, double silent_s, double error_after_s) {
  if (state == SessionState::kStreaming && silent_s < kStreamingFreshS) return {LinkLevel::kOk, detail};
  if (silent_s < error_after_s) return {LinkLevel::kDegraded, detail};
  return {LinkLevel::kError, fmt::format("no scan for {:.0f} s: {}", silent_s, detail)};
}

std::vector<std::pair<const char*, int64_t>> link_counters(const Lms100SessionCounters& c,
                                                           uint64_t publish_failures) {
  const auto v = [](const std::atomic<uint64_t>& a) { return static_cast<int64_t>(a.load()); };
  return {{"connects", v(c.connects)},
          {"connect_failures", v(c.connect_failures)},
          {"reconnects", v(c.reconnects)},
          {"timeouts", v(c.timeouts)},
          {"sfa_errors", v(c.sfa_errors)},
          {"parse_errors", v(c.parse_errors)},
          {"garbage_bytes", v(c.garbage_bytes)},
          {"resyncs", v(c.resyncs)},
          {"oversized_frames", v(c.oversized_frames)},
          {"unexpected_frames", v(c.unexpected_frames)},
          {"scans", v(c.scans)},
          {"scan_counter_gaps", v(c.scan_counter_gaps)},
          {"lost_scans", v(c.lost_scans)},
          {"implausible_scans", v(c.implausible_scans)},
          {"multi_layer_scans", v(c.multi_layer_scans)},
          {"implausible_scale", v(c.implausible_scale)},
          {"implausible_offset", v(c.implausible_offset)},
          {"implausible_scan_frequency", v(c.implausible_scan_frequency)},
          {"implausible_beam_count", v(c.implausible_beam_count)},
          {"implausible_angles", v(c.implausible_angles)},
          {"implausible_beam_timing", v(c.implausible_beam_timing)},
          {"reserved_distance_codes", v(c.reserved_distance_codes)},
          {"scans_in_bursts", v(c.scans_in_bursts)},
          {"held_scans", v(c.held_scans)},
          {"held_scans_dropped", v(c.held_scans_dropped)},
          {"held_scan_max_delay_us", c.held_scan_max_delay_us.load()},
          {"utime_not_increasing", v(c.utime_not_increasing)},
          {"clock_restarts", v(c.clock_restarts)},
          {"publish_failures", static_cast<int64_t>(publish_failures)}};
}

void LinkHealth::on_state(SessionState state, const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = state;
  detail_ = detail;
}

void LinkHealth::on_scan_published(int64_t now_us, int64_t publish_us, bool published) {
  if (!published) ++publish_failures_;
  last_scan_us_.store(now_us);
  last_publish_us_.store(publish_us);
}

std::string LinkHealth::on_scan_rejected(int64_t now_us, const std::string& detail) {
  std::lock_guard<std::mutex> lock(mutex_);
  last_rejection_us_ = now_us;
  rejection_detail_ = detail;
  ++rejections_since_log_;
  if (last_rejection_log_us_ != 0 && (now_us - last_rejection_log_us_) * 1e-6 < kRejectionLogPeriodS)
    return "";
  const std::string line = fmt::format("refused {} implausible scan{}: {}", rejections_since_log_,
                                       rejections_since_log_ == 1 ? "" : "s", detail);
  last_rejection_log_us_ = now_us;
  rejections_since_log_ = 0;
  return line;
}

LinkVerdict LinkHealth::verdict(int64_t now_us) const {
  SessionState state;
  std::string detail;
  int64_t rejected_us = 0;
  std::string rejection;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = state_;
    detail = detail_;
    rejected_us = last_rejection_us_;
    rejection = rejection_detail_;
  }
  const int64_t last = last_scan_us_.load();
  const double silent_s = (now_us - (last > 0 ? last : started_us_)) * 1e-6;
  LinkVerdict v = judge_link(state, detail, silent_s, error_after_s_);
  if (rejected_us != 0 && (now_us - rejected_us) * 1e-6 < kRejectionHoldS) {
    if (v.level == LinkLevel::kOk) v.level = LinkLevel::kDegraded;
    v.detail =
        "refusing implausible scans: " + rejection + (v.level == LinkLevel::kError ? "; " + v.detail : "");
  }
  return v;
}

}  // namespace refloc
