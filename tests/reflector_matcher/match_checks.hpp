#pragma once
// Test helper: is a MatchResult right about a synthetic scan?

#include "reflector_matcher/match_result.hpp"

#include "synthetic_detections.hpp"

namespace refloc::testing {

/// Every reported match pairs a detection with the reflector that produced it.
inline bool all_matches_correct(const MatchResult& result, const SyntheticScan& scan,
                                const ReflectorMap& map) {
  for (const ReflectorMatch& m : result.matches) {
    const int truth = scan.map_index[static_cast<size_t>(m.detection_index)];
    if (map.reflectors[static_cast<size_t>(truth)].id != m.map_id) return false;
  }
  return true;
}

/// OK but with a wrong pose (> 0.2 m or > 5 deg off) or a wrong correspondence.
inline bool is_wrong_ok(const MatchResult& result, const SyntheticScan& scan, const ReflectorMap& map,
                        const Pose2& true_map_T_laser) {
  if (result.status != MatchStatus::kOk) return false;
  return !approx_equal(result.map_T_laser, true_map_T_laser, 0.2, 5.0 * M_PI / 180.0) ||
         !all_matches_correct(result, scan, map);
}

}  // namespace refloc::testing
