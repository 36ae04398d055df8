#pragma once
// How often a landmark was seen of the times it should have been: in the field of view, near
// enough for the extractor to find a cylinder (its recall falls beyond ~7 m at 0.5 deg), and
// with no traced wall or rack in the line of sight. A cylinder is found in most of those scans;
// reflective tape passes the extractor's shape test in a minority of them (only near face-on,
// and then not always), so the fraction tells them apart where the centre does not move.

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

struct VisibilityConfig {
  double max_range = 7.0;                       ///< farther is not expected [m]
  double field_of_view = 270.0 * M_PI / 180.0;  ///< full opening angle [rad]
  /// The line of sight is tested up to this short of the centre: the cylinder's own wall or
  /// rack face stands right behind it [m].
  double near_end_margin = 0.15;
};

struct VisibilityCount {
  int expected = 0;  ///< scans it should have been seen in
  int seen = 0;      ///< of those, scans it was detected in
  double fraction() const { return expected > 0 ? static_cast<double>(seen) / expected : 0.0; }
};

/// seen_in_scan[j][k]: landmark j was detected in scan k. One count per landmark.
std::vector<VisibilityCount> count_visibility(const std::vector<Pose2>& map_T_robot,
                                              const Pose2& robot_T_laser,
                                              const std::vector<Eigen::Vector2d>& map_p_landmark,
                                              const std::vector<std::vector<char>>& seen_in_scan,
                                              const std::vector<MapOccluder>& occluders,
                                              const VisibilityConfig& config);

/// Whether the segment a-b crosses any occluder segment.
bool line_of_sight_blocked(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const std::vector<MapOccluder>& occluders);

}  // namespace refloc
