#pragma once
// The matcher pipeline: paper mode (§3.5 triangle signatures), or the default
// mode - tracking association from a prior pose, falling back to global
// relocalization over an index of map triangles when there is no prior or
// tracking fails.

#include "reflector_matcher/global_relocalizer.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/map_triangle_index.hpp"
#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/occluder_grid.hpp"
#include "reflector_matcher/paper_triangle_matcher.hpp"
#include "reflector_matcher/tracking_associator.hpp"

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <memory>
#include <vector>

namespace refloc {

class ReflectorMatcher {
 public:
  /// Builds the map's spatial grid, occluder grid and triangle index (or the paper's signature
  /// list) once.
  ReflectorMatcher(ReflectorMap map, const MatcherConfig& config);
  ReflectorMatcher(const ReflectorMatcher&) = delete;
  ReflectorMatcher& operator=(const ReflectorMatcher&) = delete;

  /// Match one scan's detections; prior may be null. result is overwritten (its vector reused).
  void match(const std::vector<ReflectorDetection>& detections, const PosePrior* prior, MatchResult& result);

  const ReflectorMap& map() const { return map_; }
  const MatcherConfig& config() const { return config_; }
  /// Triangles in the relocalization index (or the paper's list).
  size_t indexed_triangles() const;
  /// The last match() held a global OK elsewhere than the prior back as AMBIGUOUS until another
  /// scan confirms it (tracking.bare_overrule_confirm_scans).
  bool held_bare_overrule() const { return scans_since_overrule_ == 0; }
  /// The last match() was an AMBIGUOUS map-wide result that the prior settled: its best pose
  /// or one of its rivals alone inside the prior's gate (reported OK, mode TRACKING).
  bool prior_settled_ambiguity() const { return prior_settled_ambiguity_; }
  /// The last match() had a prior and tracking found fewer than min_matches pairs from it (the
  /// map-wide search answered, whatever mode the result reports).
  bool tracking_association_failed() const { return tracking_association_failed_; }

 private:
  ReflectorMap map_;
  MatcherConfig config_;
  MapGrid grid_;
  OccluderGrid occluders_;  ///< the map's walls and racks; the paper mode ignores them
  std::unique_ptr<MapTriangleIndex> index_;
  std::unique_ptr<GlobalRelocalizer> relocalizer_;
  std::unique_ptr<TrackingAssociator> tracker_;
  std::unique_ptr<PaperTriangleMatcher> paper_;
  MatchResult tracked_;  ///< a doubtful tracking result while the global search runs
  /// The last bare-minimum overrule of a prior not yet confirmed, and scans since it (-1: none;
  /// 0: held back in the last match()).
  Pose2 unconfirmed_overrule_;
  int scans_since_overrule_ = -1;
  /// A global OK that overrules prior on the bare minimum of pairs becomes AMBIGUOUS unless it
  /// repeats the unconfirmed one (tracking.bare_overrule_confirm_scans).
  void confirm_bare_overrule(const PosePrior& prior, MatchResult& result);
  bool prior_settled_ambiguity_ = false;
  bool tracking_association_failed_ = false;
  /// After tracking failed: a map-wide result inside the prior's gate is the prior confirmed
  /// (mode TRACKING), and an AMBIGUOUS one is settled by it when it admits one hypothesis alone.
  void decide_with_prior(const PosePrior& prior, const std::vector<ReflectorDetection>& detections,
                         MatchResult& result);
};

}  // namespace refloc
