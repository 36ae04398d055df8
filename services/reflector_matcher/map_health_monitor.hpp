#pragma once
// Map maintenance inside the matcher service, without LCM: keeps the last laser scans (for the
// line of sight), feeds every OK scan's decision to MapEvidence, and once a period gives the
// report for MAP_HEALTH with one line per state change since the last report.

#include "reflector_matcher/map_evidence.hpp"
#include "reflector_matcher/map_health_config.hpp"
#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/scan_evidence.hpp"

#include "common/laser_scan.hpp"
#include "common/log_rate_limiter.hpp"
#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace refloc {

/// One state change for the log: key names what changed (rate-limit per key), text says how.
struct MapHealthChange {
  std::string key;   ///< "reflector 7", "candidate 3"
  std::string text;  ///< "reflector 7 missing (was ok): expected 212 times with a clear sight, seen 0"
  bool warning = false;
};

class MapHealthMonitor {
 public:
  /// map must outlive the monitor.
  MapHealthMonitor(const ReflectorMap& map, const SensorVisibilityConfig& sensor,
                   const MapHealthConfig& config);

  /// A laser scan, kept until its detections are matched (a few scans back).
  void on_scan(const LaserScan& scan);
  /// The matcher's decision for the detections of the scan stamped utime [us]; used when OK
  /// and, with require_fused_prior, tracked from the fused POSE (fused_prior).
  void on_match(int64_t utime, const std::vector<ReflectorDetection>& detections, const MatchResult& result,
                bool fused_prior);

  /// The report at utime [us]; changes gets the lines to log: each reflector's state when it
  /// differs from the one last logged, each new candidate, at most one line per reflector or
  /// candidate in 10 s (monotonic_us [us]): a flapping state is logged as it stands then.
  const MapHealthReport& report(int64_t utime, int64_t monotonic_us, std::vector<MapHealthChange>& changes);
  /// OK scans whose laser scan was not at hand: no expected-unseen evidence from them.
  int64_t scans_without_laser_scan() const { return scans_without_laser_scan_; }

 private:
  const LaserScan* scan_at(int64_t utime) const;
  bool may_log(const std::string& key, int64_t monotonic_us);
  static constexpr int kNotLogged = -2;  ///< a candidate whose line is still held back

  bool require_fused_prior_;
  ScanEvidenceBuilder builder_;
  MapEvidence evidence_;
  std::array<LaserScan, 8> scans_;  ///< ring of the latest scans
  size_t next_scan_ = 0;
  ScanEvidence scan_evidence_;
  MapHealthReport report_;
  std::map<int, ReflectorHealth> logged_states_;  ///< by reflector id: the state last logged
  std::map<int64_t, int> logged_candidates_;      ///< cluster key -> moved_reflector_id last logged
  LogRateLimiter change_log_{10'000'000};         ///< per reflector or candidate: one line in 10 s
  int64_t scans_without_laser_scan_ = 0;
};

}  // namespace refloc
