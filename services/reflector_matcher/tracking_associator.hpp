#pragma once
// Association from a prior pose: each map reflector near the view is predicted
// into the laser frame and paired with the nearest detection inside a
// Mahalanobis gate that adds the prior's uncertainty (grown with range through
// the heading) to the detection's covariance; pairs are unique. The pose is then
// refitted to those pairs and the association repeated with the verifier's
// coarse-then-fine Euclidean gates, so a prior 0.2 m / 3 deg off still gives
// the right pairs at 20 m. A reflector the map's occluders hide from the prior's
// position takes no detection.

#include "reflector_matcher/hypothesis_verifier.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/reflector_visibility.hpp"

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <vector>

namespace refloc {

/// The prior's covariance with its standard deviations floored (tracking.prior_min_sigma_*): a
/// prior claiming millimetres would gate out a reflector's real scatter.
Eigen::Matrix3d floored_prior_covariance(const PosePrior& prior, const TrackingConfig& tracking);

class TrackingAssociator {
 public:
  /// map, grid and occluders (null: none) must outlive the associator; relocalization's gates
  /// verify the association.
  TrackingAssociator(const ReflectorMap& map, const MapGrid& grid, const TrackingConfig& tracking,
                     const SensorVisibilityConfig& sensor, const RelocalizationConfig& relocalization,
                     int min_matches, const OccluderGrid* occluders = nullptr);

  /// Fills result (mode TRACKING); returns false (status LOST) when fewer than
  /// min_matches detections could be associated, so the caller can relocalize.
  bool associate(const std::vector<ReflectorDetection>& detections, const PosePrior& prior,
                 MatchResult& result);

 private:
  struct Candidate {
    double mahalanobis2;
    int predicted_index;
    int detection_index;
  };

  const ReflectorMap& map_;
  const MapGrid& grid_;
  const OccluderGrid* occluders_;
  TrackingConfig tracking_;
  SensorVisibilityConfig sensor_;
  int min_matches_;
  HypothesisVerifier refit_verifier_;
  std::vector<int> scratch_;
  std::vector<PredictedReflector> predicted_;
  SightCache sight_;  ///< of predicted_ from the prior's position
  std::vector<Candidate> candidates_;
  std::vector<char> predicted_used_;
  std::vector<char> detection_used_;
};

}  // namespace refloc
