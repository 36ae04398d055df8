#pragma once
// Relocalization without a prior: every triangle of detections looks up the map
// triangles with the same sorted sides, each gives a map_T_laser hypothesis by a
// rigid fit, each hypothesis is verified against the whole map, the best wins,
// and a substantially different runner-up that explains the scan nearly as well
// makes the answer AMBIGUOUS rather than a coin toss.

#include "reflector_matcher/hypothesis_verifier.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/map_triangle_index.hpp"
#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/triangle_signature.hpp"

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace refloc {

class GlobalRelocalizer {
 public:
  /// map, grid, index and occluders (null: none) must outlive the relocalizer.
  GlobalRelocalizer(const ReflectorMap& map, const MapGrid& grid, const MapTriangleIndex& index,
                    const RelocalizationConfig& relocalization, const SensorVisibilityConfig& sensor,
                    int min_matches, const OccluderGrid* occluders = nullptr);

  /// Fills result (status, matches, scores, map_T_laser; mode = GLOBAL).
  void relocalize(const std::vector<ReflectorDetection>& detections, MatchResult& result);

  /// Hypotheses verified by the last call (for tests and benchmarks).
  size_t hypotheses_verified() const { return scored_.size(); }
  /// Poses of the last call that rivalled its best (the call was AMBIGUOUS when it had matches
  /// and this is not empty).
  const std::vector<Pose2>& rivals() const { return rivals_; }
  /// Makes result (of the last relocalize()) the given rival's, verified again, status OK; false
  /// (result unchanged) when the rival explains too little of the scan. For a caller with
  /// evidence the search lacks (a prior that admits this rival alone).
  bool adopt_rival(const Pose2& rival, const std::vector<ReflectorDetection>& detections,
                   MatchResult& result);

 private:
  /// A pose from a triangle lookup. may_win: some triangle proposed it within the fixed
  /// side_tolerance; one found only through the tolerance its detections' covariances widen can
  /// make the scan AMBIGUOUS as a rival but is never the answer itself: a looser lookup is
  /// evidence enough to doubt a pose, not to assert one (without occluders, letting it win
  /// raised the wrong fixes from scratch from 4 to 14 per 200,000 demo-hall scans).
  struct Hypothesis {
    Pose2 map_T_laser;
    bool may_win = true;
  };
  struct Scored {
    Pose2 map_T_laser;
    double score;
    int matched;
  };
  void generate_hypotheses(const std::vector<ReflectorDetection>& detections);
  /// Per sorted side of the triangle of detections det: side_tolerance, widened by the side's
  /// own standard deviation (relocalization.side_tolerance_sigmas), capped.
  std::array<double, 3> side_tolerances(const std::vector<ReflectorDetection>& detections,
                                        const std::array<int, 3>& det, const SortedSides& s) const;
  void remove_duplicate_hypotheses();
  bool explains_enough(int matched, double score, size_t ndetections) const;
  void fill_matches(MatchResult& result) const;  ///< from best_associations_

  const ReflectorMap& map_;
  RelocalizationConfig relocalization_;
  int min_matches_;
  const MapTriangleIndex& index_;
  HypothesisVerifier verifier_;
  std::vector<int> nearest_;  ///< detection indices used for triples, nearest first
  std::vector<Hypothesis> hypotheses_;
  std::vector<Hypothesis> unique_;
  std::vector<std::pair<uint64_t, size_t>> keyed_;
  std::vector<Scored> scored_;
  std::vector<Association> best_associations_;
  std::vector<Pose2> rivals_;
};

}  // namespace refloc
