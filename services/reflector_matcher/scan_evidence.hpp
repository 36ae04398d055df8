#pragma once
// What one OK scan says about the map, from the matcher's decision: the matched reflectors'
// detections in the map frame (each from a pose fitted without it), the unmatched detections
// in the map frame, and the map reflectors that should have been seen but were not. "Should"
// is the visibility prediction (range, field of view, shadowing by nearer reflectors) checked
// against the scan itself: the beams toward the reflector must reach its place, so one hidden
// by a rack, a person or another robot is no evidence of a missing reflector.

#include "reflector_matcher/map_evidence.hpp"
#include "reflector_matcher/map_grid.hpp"
#include "reflector_matcher/map_health_config.hpp"
#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/occluder_grid.hpp"
#include "reflector_matcher/reflector_visibility.hpp"

#include "common/laser_scan.hpp"
#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <unordered_map>
#include <vector>

namespace refloc {

/// Whether the beams of scan toward a cylinder of radius [m] at range [m] and bearing [rad]
/// (laser frame) reach its near face, within tolerance [m]: no echo counts as reaching, a
/// dazzled beam or a beam outside the scan does not.
bool line_of_sight_clear(const LaserScan& scan, double range, double bearing, double radius,
                         double tolerance);

class ScanEvidenceBuilder {
 public:
  /// map must outlive the builder.
  ScanEvidenceBuilder(const ReflectorMap& map, const SensorVisibilityConfig& sensor,
                      const MapHealthConfig& config);

  /// The evidence of an OK result (out.seen etc. cleared first). scan: the laser scan the
  /// detections came from; null when it is not at hand: then nothing counts as expected-unseen.
  void build(int64_t utime, const std::vector<ReflectorDetection>& detections, const MatchResult& result,
             const LaserScan* scan, ScanEvidence& out);

 private:
  void add_sightings(const std::vector<ReflectorDetection>& detections, const MatchResult& result,
                     ScanEvidence& out);
  bool fit(const std::vector<ReflectorDetection>& detections, const MatchResult& result, int skip,
           Pose2& map_T_laser, double& rms) const;
  void add_expected_unseen(const MatchResult& result, const LaserScan& scan, ScanEvidence& out);

  const ReflectorMap& map_;
  MapGrid grid_;
  OccluderGrid occluders_;
  SensorVisibilityConfig sensor_;
  MapHealthConfig config_;
  std::unordered_map<int, int> index_of_id_;
  std::vector<int> scratch_;
  std::vector<PredictedReflector> predicted_;
  std::vector<char> detection_matched_;
  std::vector<char> reflector_matched_;  ///< by map index, reset after each scan
};

}  // namespace refloc
