#pragma once
// A surveyed map against the truth (the world's map, a total-station survey): the rigid
// transform that best lays the map onto the truth, found without ids (a surveyed map numbers
// its reflectors its own way), then per reflector the error, its sigma and whether the truth
// lies inside 3 sigma; map entries with no real reflector (a distractor mapped, a reflector
// mapped twice) and real reflectors the map lacks. refloc-survey compare prints it.

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

struct MapComparisonOptions {
  /// A map entry farther than this from every truth reflector after alignment is extra [m].
  double match_gate = 0.1;
  /// false: compare in the frames as given (a map surveyed with anchors in the truth's frame).
  bool align = true;
};

struct ReflectorComparison {
  int map_id = 0;
  int truth_id = 0;
  Eigen::Vector2d truth_p_map = Eigen::Vector2d::Zero();  ///< the map's entry, aligned [m]
  Eigen::Vector2d truth_p = Eigen::Vector2d::Zero();      ///< [m]
  double error = 0.0;                                     ///< |truth_p_map - truth_p| [m]
  bool has_covariance = false;
  double sigma = 0.0;        ///< sqrt of the largest eigenvalue of the map's covariance [m]
  double mahalanobis = 0.0;  ///< of the error under that covariance [-]
};

struct MapComparison {
  bool aligned = false;  ///< an alignment was found (or not asked for)
  Pose2 truth_T_map;
  std::vector<ReflectorComparison> matched;  ///< in the map's order
  std::vector<int> extra_map_ids;            ///< map entries without a truth reflector
  std::vector<int> missing_truth_ids;        ///< truth reflectors without a map entry
  double rms = 0.0;                          ///< over matched [m]
  double worst = 0.0;                        ///< [m]
  int worst_map_id = 0;
  /// The map's scale against the truth (a similarity fit after the rigid one: the aligned map
  /// scaled about the pairs' centroid) [1e-6], and the RMS left after it [m]: a survey whose
  /// ranges read long comes out too large, every reflector pushed out from the middle.
  double scale_ppm = 0.0;
  double rms_after_scale = 0.0;
  int with_covariance = 0;
  int within_3_sigma = 0;  ///< of those with a covariance: Mahalanobis distance <= 3
};

MapComparison compare_maps(const ReflectorMap& map, const ReflectorMap& truth,
                           const MapComparisonOptions& options = {});

/// The comparison as printed: one line per reflector, then RMS, worst, 3-sigma fraction, extras.
std::string comparison_text(const MapComparison& comparison);
/// One row per matched reflector, in the map's frame (the error rotated back), for pictures:
/// map_id,truth_id,error_x_mm,error_y_mm,error_mm,sigma_mm,mahalanobis.
std::string comparison_csv(const MapComparison& comparison);

}  // namespace refloc
