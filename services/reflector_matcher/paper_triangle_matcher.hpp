#pragma once
// The paper's §3.5 matching, kept as the baseline: every triple of detections is
// reduced to its largest angle and the two sides adjacent to it, and compared with
// the same signature of every map triangle; each agreeing pair of triangles votes
// for three correspondences and every detection takes its most voted reflector.
// Signatures are mirror-invariant and nothing checks the pose as a whole, which
// is why this is not the default mode.

#include "reflector_matcher/match_result.hpp"
#include "reflector_matcher/matcher_config.hpp"
#include "reflector_matcher/triangle_signature.hpp"

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"

#include <array>
#include <vector>

namespace refloc {

class PaperTriangleMatcher {
 public:
  /// Precomputes the signature of every map triangle with sides <= max_triangle_side [m]
  /// (at most max_triangles of them).
  PaperTriangleMatcher(const ReflectorMap& map, const PaperMatchingConfig& paper, double max_triangle_side,
                       size_t max_triangles, int min_matches);

  /// Fills result (mode GLOBAL): OK with >= min_matches correspondences, AMBIGUOUS when a
  /// detection's vote is tied between reflectors, else LOST.
  void match(const std::vector<ReflectorDetection>& detections, MatchResult& result);

  size_t map_triangles() const { return map_triangles_.size(); }

 private:
  struct MapTriangle {
    LargestAngleSignature signature;
    std::array<int, 3> vertex{};  ///< map indices of the signature's vertices 0, 1, 2
  };
  struct Vote {
    int count;
    int detection_index;
    int map_index;
  };

  const ReflectorMap& map_;
  PaperMatchingConfig paper_;
  int min_matches_;
  std::vector<MapTriangle> map_triangles_;
  std::vector<int> votes_;  ///< detections x map reflectors
  std::vector<Vote> ranked_;
  std::vector<char> detection_used_, map_used_;
};

}  // namespace refloc
