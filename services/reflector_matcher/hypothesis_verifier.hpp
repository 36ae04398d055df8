#pragma once
// Scores a map_T_laser hypothesis against the whole scan: every map reflector
// predicted in view is looked for among the detections, so a pose that
// explains three detections by chance but predicts reflectors nobody saw loses.
// A reflector the map's occluders hide from the hypothesised laser position is
// neither a match for a detection nor missed; one they partly hide is no
// evidence either way when unseen.

#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/occluder_grid.hpp"
#include "reflector_matcher/reflector_visibility.hpp"

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <vector>

namespace refloc {

/// One detection explained by one map reflector (indices, not ids).
struct Association {
  int detection_index = -1;
  int map_index = -1;
};

struct Verification {
  Pose2 map_T_laser;     ///< the hypothesis refitted to all its associations
  double score = 0.0;    ///< matched - missed_penalty * missed - unexplained_penalty * unexplained
  int matched = 0;       ///< detections explained
  int missed = 0;        ///< reflectors expected in view, not shadowed or occluded, not seen
  int unexplained = 0;   ///< detections no reflector explains
  int inconsistent = 0;  ///< pairs dropped (or all, for 3) by the fit consistency test
};

/// Upper bound of a chi-square with dof degrees of freedom at `sigmas` standard normal
/// deviations (Wilson-Hilferty: within ~1 % of the exact quantile for dof >= 3).
double chi_square_bound(int dof, double sigmas);

class HypothesisVerifier {
 public:
  /// map, grid and occluders (null: none) must outlive the verifier; the gates and penalties
  /// are relocalization's.
  HypothesisVerifier(const ReflectorMap& map, const MapGrid& grid, const SensorVisibilityConfig& sensor,
                     const RelocalizationConfig& relocalization, const OccluderGrid* occluders = nullptr);

  /// Associate with the coarse gate, refit, associate with the fine gate, score.
  Verification verify(const Pose2& map_T_laser, const std::vector<ReflectorDetection>& detections);

  /// Associations of the last verify() (fine gate).
  const std::vector<Association>& associations() const { return associations_; }

  /// Unique nearest-neighbour association within gate [m] of the reflectors not hidden by an
  /// occluder; returns the number of associations.
  int associate(const Pose2& map_T_laser, const std::vector<ReflectorDetection>& detections, double gate);

 private:
  struct Candidate {
    double distance2;
    int predicted_index;
    int detection_index;
  };
  bool refit(const std::vector<ReflectorDetection>& detections, Pose2& map_T_laser) const;
  /// Removes, worst first, associations farther than the fine gate from the pose the others fit.
  void drop_unsupported_pairs(const std::vector<ReflectorDetection>& detections);
  /// Chi-square of the associations' residuals at map_T_laser.
  double fit_chi2(const std::vector<ReflectorDetection>& detections, const Pose2& map_T_laser) const;
  /// The consistency test (fit_consistency_sigmas); refits map_T_laser; pairs dropped.
  int drop_inconsistent_pairs(const std::vector<ReflectorDetection>& detections, Pose2& map_T_laser);
  void remove_association(size_t index);

  const ReflectorMap& map_;
  const MapGrid& grid_;
  const OccluderGrid* occluders_;
  SensorVisibilityConfig sensor_;
  RelocalizationConfig relocalization_;
  std::vector<int> scratch_;
  std::vector<PredictedReflector> predicted_;
  SightCache sight_;  ///< of predicted_ from the pose of the last associate()
  std::vector<char> predicted_matched_;
  std::vector<char> detection_used_;
  std::vector<Candidate> candidates_;
  std::vector<Association> associations_;
  std::vector<Association> all_pairs_;  ///< drop_inconsistent_pairs' copy of associations_
};

}  // namespace refloc
