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

LinkVerdict LinkHealth::verdict(int64_t now_us) const {
  SessionState state;
  std::string detail;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    state = state_;
    detail = detail_;
  }
  const int64_t last = last_scan_us_.load();
  const double silent_s = (now_us - (last > 0 ? last : started_us_)) * 1e-6;
  return judge_link(state, detail, silent_s, error_after_s_);
}

}  // namespace refloc
