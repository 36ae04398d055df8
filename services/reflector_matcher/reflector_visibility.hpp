#pragma once
// Which map reflectors the laser should see from a given pose: range, field of
// view, and shadowing by nearer reflectors.

#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/matcher_config.hpp"

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// A map reflector predicted into the laser frame.
struct PredictedReflector {
  int map_index = -1;
  Eigen::Vector2d laser_p = Eigen::Vector2d::Zero();  ///< [m]
  double range = 0.0;                                 ///< [m]
  double bearing = 0.0;                               ///< [rad]
  bool in_view = false;  ///< strictly inside range limits and field of view (margin not used)
};

/// Fills out (cleared first) with the map reflectors near the view of map_T_laser: within the
/// range limits and field of view widened by margin [m]. scratch is reused working memory.
void predict_reflectors(const ReflectorMap& map, const MapGrid& grid, const Pose2& map_T_laser,
                        const SensorVisibilityConfig& sensor, double margin, std::vector<int>& scratch,
                        std::vector<PredictedReflector>& out);

/// True when a nearer reflector in predicted shadows predicted[k] (their angular extents overlap).
bool is_shadowed(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k);

}  // namespace refloc
