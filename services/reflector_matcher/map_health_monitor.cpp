#include "reflector_matcher/map_health_monitor.hpp"

#include <fmt/format.h>

namespace refloc {
namespace {

std::string reflector_change_text(const ReflectorHealthEntry& r, ReflectorHealth was) {
  std::string text =
      fmt::format("reflector {} {} (was {}): seen {}, expected and unseen {}", r.id,
                  reflector_health_name(r.state), reflector_health_name(was), r.seen, r.expected_missing);
  if (r.state == ReflectorHealth::kMoved) {
    text += fmt::format(", offset ({:+.3f}, {:+.3f}) m +- ({:.3f}, {:.3f})", r.offset.x(), r.offset.y(),
                        r.offset_sigma.x(), r.offset_sigma.y());
  }
  return text;
}

std::string candidate_text(const MapCandidate& c) {
  return fmt::format("candidate at ({:.3f}, {:.3f}) m +- ({:.3f}, {:.3f}), {} sightings over {:.1f} m{}",
                     c.map_p.x(), c.map_p.y(), c.sigma.x(), c.sigma.y(), c.sightings, c.viewpoint_spread,
                     c.moved_reflector_id < 0
                         ? ": an unmapped reflector"
                         : fmt::format(": the new place of reflector {}", c.moved_reflector_id));
}

}  // namespace

MapHealthMonitor::MapHealthMonitor(const ReflectorMap& map, const SensorVisibilityConfig& sensor,
                                   const MapHealthConfig& config)
    : require_fused_prior_(config.require_fused_prior),
      builder_(map, sensor, config),
      evidence_(map, config) {
  for (const MapReflector& r : map.reflectors) logged_states_[r.id] = ReflectorHealth::kUnconfirmed;
}

void MapHealthMonitor::on_scan(const LaserScan& scan) {
  LaserScan& slot = scans_[next_scan_];
  slot.utime = scan.utime;
  slot.start_angle = scan.start_angle;
  slot.angle_increment = scan.angle_increment;
  slot.range_min = scan.range_min;
  slot.range_max = scan.range_max;
  slot.ranges.assign(scan.ranges.begin(), scan.ranges.end());  // capacity reused: no allocation per scan
  next_scan_ = (next_scan_ + 1) % scans_.size();
}

const LaserScan* MapHealthMonitor::scan_at(int64_t utime) const {
  for (const LaserScan& s : scans_) {
    if (s.utime == utime && !s.ranges.empty()) return &s;
  }
  return nullptr;
}

void MapHealthMonitor::on_match(int64_t utime, const std::vector<ReflectorDetection>& detections,
                                const MatchResult& result, bool fused_prior) {
  if (result.status != MatchStatus::kOk || (require_fused_prior_ && !fused_prior)) return;
  const LaserScan* scan = scan_at(utime);
  if (scan == nullptr) ++scans_without_laser_scan_;
  builder_.build(utime, detections, result, scan, scan_evidence_);
  evidence_.add(scan_evidence_);
}

bool MapHealthMonitor::may_log(const std::string& key, int64_t monotonic_us) {
  int64_t held_back = 0;  // held-back lines are not repeated: the state now is what is logged
  return change_log_.allow(key, monotonic_us, held_back);
}

const MapHealthReport& MapHealthMonitor::report(int64_t utime, int64_t monotonic_us,
                                                std::vector<MapHealthChange>& changes) {
  changes.clear();
  evidence_.report(utime, report_);
  for (const ReflectorHealthEntry& r : report_.reflectors) {
    ReflectorHealth& logged = logged_states_[r.id];
    if (r.state == logged) continue;
    if (logged == ReflectorHealth::kUnconfirmed && r.state == ReflectorHealth::kOk) {
      logged = r.state;  // the normal start, not news
      continue;
    }
    const std::string key = fmt::format("reflector {}", r.id);
    if (!may_log(key, monotonic_us)) continue;  // the state now is logged once the interval has passed
    const bool bad = r.state == ReflectorHealth::kMissing || r.state == ReflectorHealth::kMoved;
    changes.push_back({key, reflector_change_text(r, logged), bad});
    logged = r.state;
  }
  std::map<int64_t, int> candidates;
  for (const MapCandidate& c : report_.candidates) {
    candidates[c.key] = c.moved_reflector_id;
    const auto before = logged_candidates_.find(c.key);
    if (before != logged_candidates_.end() && before->second == c.moved_reflector_id) continue;
    const std::string key = fmt::format("candidate {}", c.key);
    if (may_log(key, monotonic_us))
      changes.push_back({key, candidate_text(c), true});
    else
      candidates[c.key] = before == logged_candidates_.end() ? kNotLogged : before->second;
  }
  for (const auto& [key, moved_id] : logged_candidates_) {
    if (candidates.count(key) == 0 && moved_id != kNotLogged)
      changes.push_back({fmt::format("candidate {}", key), "a candidate no longer holds", false});
  }
  logged_candidates_.swap(candidates);
  return report_;
}

}  // namespace refloc
