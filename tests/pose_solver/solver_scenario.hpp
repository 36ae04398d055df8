#pragma once
// Test helper: a map, a true robot pose and the matches a perfect matcher would give.

#include "synthetic_detections.hpp"

namespace refloc::testing {

/// Matches of a synthetic scan to the reflectors that produced it.
inline std::vector<ReflectorMatch> true_matches(const SyntheticScan& scan, const ReflectorMap& map) {
  std::vector<ReflectorMatch> matches;
  for (size_t d = 0; d < scan.detections.size(); ++d) {
    const MapReflector& r = map.reflectors[static_cast<size_t>(scan.map_index[d])];
    matches.push_back({static_cast<int>(d), r.id, r.map_p_center, r.radius});
  }
  return matches;
}

/// Eight reflectors around a 16 m x 12 m hall: a good geometry from its middle.
inline ReflectorMap hall_map() {
  return map_from_points({{0, 0}, {8, -1}, {16, 0}, {17, 6}, {16, 12}, {8, 13}, {0, 12}, {-1, 6}});
}

/// The paper's mount: the laser at a corner of the platform, not at its centre.
inline Pose2 corner_mount() { return Pose2{-0.4, 0.3, 0.0}; }

}  // namespace refloc::testing
