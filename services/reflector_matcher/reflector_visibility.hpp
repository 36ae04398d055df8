#pragma once
// Which map reflectors the laser should see from a given pose: range, field of
// view, shadowing by nearer reflectors, and the map's occluders (walls, racks).

#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/occluder_grid.hpp"

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

/// How much of a reflector's near side the laser sees past the map's occluders.
enum class LineOfSight : signed char {
  kClear,    ///< every sampled beam reaches the cylinder: expected in the scan
  kPartial,  ///< some do: may be detected, but a cut cylinder may also be rejected (no evidence)
  kBlocked,  ///< none: behind a wall, neither expected nor a match for a detection
};

/// Beams aimed across the line of sight at the centre and at +-this fraction of the radius:
/// the outer quarter of a cylinder returns at grazing incidence, too weak to count on.
inline constexpr double kSightEdgeFraction = 0.75;

/// Whether beam b of the three aimed at reflector from map_p_laser [m] (0: at the centre,
/// 1 and 2: +-kSightEdgeFraction radii across the line of sight), ending where it meets the
/// cylinder's near surface, crosses an occluder.
bool sight_beam_blocked(const OccluderGrid& occluders, const Eigen::Vector2d& map_p_laser,
                        const MapReflector& reflector, int b);

/// The sight from map_p_laser [m] to the part of reflector's cylinder the beams hit.
LineOfSight line_of_sight(const OccluderGrid& occluders, const Eigen::Vector2d& map_p_laser,
                          const MapReflector& reflector);

/// The sight of each reflector of a predicted list from one laser position, beam by beam as
/// asked: a hypothesis needs it only for the few reflectors a detection could match or that
/// would count as missed, and the centre beam alone answers "hidden?" for one in plain view and
/// "clear?" for one behind a wall. Without occluders nothing is hidden, all clear, at no cost.
class SightCache {
 public:
  /// Forget the last position; occluders may be null (none).
  void reset(const OccluderGrid* occluders, const Eigen::Vector2d& map_p_laser, size_t predicted_count);
  /// LineOfSight::kBlocked: predicted[k] is neither expected nor a match for a detection.
  bool hidden(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k);
  /// LineOfSight::kClear: predicted[k] unseen is evidence against the pose.
  bool clear(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k);

 private:
  bool beam_blocked(const ReflectorMap& map, const std::vector<PredictedReflector>& predicted, size_t k,
                    int b);

  const OccluderGrid* occluders_ = nullptr;
  Eigen::Vector2d map_p_laser_ = Eigen::Vector2d::Zero();
  std::vector<unsigned char> state_;  ///< per reflector: bit b = beam b tested, bit b + 3 = blocked
};

}  // namespace refloc
