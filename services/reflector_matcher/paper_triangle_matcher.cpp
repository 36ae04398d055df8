#include "reflector_matcher/paper_triangle_matcher.hpp"

#include "reflector_matcher/map_triangle_index.hpp"
#include "reflector_matcher/rigid_fit_2d.hpp"

#include <algorithm>

namespace refloc {

PaperTriangleMatcher::PaperTriangleMatcher(const ReflectorMap& map, const PaperMatchingConfig& paper,
                                           double max_triangle_side, size_t max_triangles, int min_matches)
    : map_(map), paper_(paper), min_matches_(min_matches) {
  std::vector<IndexedTriangle> triangles;
  enumerate_map_triangles(map, 0.0, max_triangle_side, max_triangles, triangles);
  map_triangles_.reserve(triangles.size());
  for (const IndexedTriangle& t : triangles) {
    MapTriangle m;
    m.vertex = {t.opposite[0], t.opposite[1], t.opposite[2]};
    m.signature = largest_angle_signature({map.reflectors[static_cast<size_t>(m.vertex[0])].map_p_center,
                                           map.reflectors[static_cast<size_t>(m.vertex[1])].map_p_center,
                                           map.reflectors[static_cast<size_t>(m.vertex[2])].map_p_center});
    map_triangles_.push_back(m);
  }
}

void PaperTriangleMatcher::match(const std::vector<ReflectorDetection>& detections, MatchResult& result) {
  result.mode = MatchMode::kGlobal;
  result.status = MatchStatus::kLost;
  result.matches.clear();
  result.hypothesis_score = 0.0;
  result.runner_up_score = 0.0;
  result.ndetections = static_cast<int>(detections.size());
  const size_t nd = detections.size(), nm = map_.reflectors.size();
  votes_.assign(nd * nm, 0);

  for (size_t i = 0; i < nd; ++i) {
    for (size_t j = i + 1; j < nd; ++j) {
      for (size_t k = j + 1; k < nd; ++k) {
        const std::array<size_t, 3> det = {i, j, k};
        const LargestAngleSignature sig = largest_angle_signature(
            {detections[i].laser_p_center, detections[j].laser_p_center, detections[k].laser_p_center});
        for (const MapTriangle& m : map_triangles_) {
          if (!signatures_match(sig, m.signature, paper_.side_tolerance, paper_.angle_tolerance)) continue;
          // Apex to apex, end of the long side to end of the long side, and so on.
          const auto vote = [&](int det_vertex, int map_vertex) {
            ++votes_[det[static_cast<size_t>(det_vertex)] * nm +
                     static_cast<size_t>(m.vertex[static_cast<size_t>(map_vertex)])];
          };
          vote(sig.apex, m.signature.apex);
          vote(sig.long_end, m.signature.long_end);
          vote(sig.short_end, m.signature.short_end);
        }
      }
    }
  }

  ranked_.clear();
  bool tie = false;
  for (size_t d = 0; d < nd; ++d) {
    int best = 0, second = 0;
    for (size_t m = 0; m < nm; ++m) {
      const int v = votes_[d * nm + m];
      if (v <= 0) continue;
      ranked_.push_back({v, static_cast<int>(d), static_cast<int>(m)});
      if (v > best) {
        second = best;
        best = v;
      } else if (v > second) {
        second = v;
      }
    }
    tie = tie || (best > 0 && best == second);
  }
  std::sort(ranked_.begin(), ranked_.end(), [](const Vote& a, const Vote& b) { return a.count > b.count; });
  detection_used_.assign(nd, 0);
  map_used_.assign(nm, 0);
  RigidFit2d fit;
  for (const Vote& v : ranked_) {
    const auto d = static_cast<size_t>(v.detection_index), m = static_cast<size_t>(v.map_index);
    if (detection_used_[d] || map_used_[m]) continue;
    detection_used_[d] = map_used_[m] = 1;
    const MapReflector& r = map_.reflectors[m];
    result.matches.push_back({v.detection_index, r.id, r.map_p_center, r.radius});
    result.hypothesis_score += v.count;
    fit.add(detections[d].laser_p_center, r.map_p_center);
  }
  fit.solve(result.map_T_laser);
  if (static_cast<int>(result.matches.size()) < min_matches_) {
    result.matches.clear();
    return;
  }
  result.status = tie ? MatchStatus::kAmbiguous : MatchStatus::kOk;
}

}  // namespace refloc
