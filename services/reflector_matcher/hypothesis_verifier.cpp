#include "reflector_matcher/hypothesis_verifier.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <algorithm>

namespace refloc {

HypothesisVerifier::HypothesisVerifier(const ReflectorMap& map, const MapGrid& grid,
                                       const SensorVisibilityConfig& sensor,
                                       const RelocalizationConfig& relocalization,
                                       const OccluderGrid* occluders)
    : map_(map), grid_(grid), occluders_(occluders), sensor_(sensor), relocalization_(relocalization) {}

int HypothesisVerifier::associate(const Pose2& map_T_laser, const std::vector<ReflectorDetection>& detections,
                                  double gate) {
  predict_reflectors(map_, grid_, map_T_laser, sensor_, gate, scratch_, predicted_);
  sight_.reset(occluders_, map_T_laser.translation(), predicted_.size());
  const double gate2 = gate * gate;
  candidates_.clear();
  for (size_t k = 0; k < predicted_.size(); ++k) {
    for (size_t d = 0; d < detections.size(); ++d) {
      const double d2 = (detections[d].laser_p_center - predicted_[k].laser_p).squaredNorm();
      if (d2 <= gate2) candidates_.push_back({d2, static_cast<int>(k), static_cast<int>(d)});
    }
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const Candidate& a, const Candidate& b) { return a.distance2 < b.distance2; });
  predicted_matched_.assign(predicted_.size(), 0);
  detection_used_.assign(detections.size(), 0);
  associations_.clear();
  for (const Candidate& c : candidates_) {
    if (predicted_matched_[static_cast<size_t>(c.predicted_index)] ||
        detection_used_[static_cast<size_t>(c.detection_index)] ||
        sight_.hidden(map_, predicted_, static_cast<size_t>(c.predicted_index)))
      continue;
    predicted_matched_[static_cast<size_t>(c.predicted_index)] = 1;
    detection_used_[static_cast<size_t>(c.detection_index)] = 1;
    associations_.push_back(
        {c.detection_index, predicted_[static_cast<size_t>(c.predicted_index)].map_index});
  }
  return static_cast<int>(associations_.size());
}

bool HypothesisVerifier::refit(const std::vector<ReflectorDetection>& detections, Pose2& map_T_laser) const {
  RigidFit2d fit;
  for (const Association& a : associations_) {
    fit.add(detections[static_cast<size_t>(a.detection_index)].laser_p_center,
            map_.reflectors[static_cast<size_t>(a.map_index)].map_p_center);
  }
  return fit.count() >= 3 && fit.solve(map_T_laser);
}

void HypothesisVerifier::drop_unsupported_pairs(const std::vector<ReflectorDetection>& detections) {
  // A distractor beside a reflector (tape on a pillar, a metal plate) can join the fine gate
  // only because the pose refitted with it bends towards it; judged against the pose the other
  // pairs give on their own, it misses. With fewer than 4 pairs there is no such other pose.
  const double gate2 = relocalization_.verify_fine_gate * relocalization_.verify_fine_gate;
  while (associations_.size() >= 4) {
    double worst2 = gate2;
    size_t worst = associations_.size();
    for (size_t i = 0; i < associations_.size(); ++i) {
      RigidFit2d others;
      for (size_t j = 0; j < associations_.size(); ++j) {
        if (j == i) continue;
        others.add(detections[static_cast<size_t>(associations_[j].detection_index)].laser_p_center,
                   map_.reflectors[static_cast<size_t>(associations_[j].map_index)].map_p_center);
      }
      Pose2 map_T_laser;
      if (!others.solve(map_T_laser)) continue;
      const double r2 =
          (map_T_laser * detections[static_cast<size_t>(associations_[i].detection_index)].laser_p_center -
           map_.reflectors[static_cast<size_t>(associations_[i].map_index)].map_p_center)
              .squaredNorm();
      if (r2 > worst2) worst2 = r2, worst = i;
    }
    if (worst == associations_.size()) return;
    for (size_t k = 0; k < predicted_.size(); ++k) {
      if (predicted_[k].map_index == associations_[worst].map_index) predicted_matched_[k] = 0;
    }
    detection_used_[static_cast<size_t>(associations_[worst].detection_index)] = 0;
    associations_.erase(associations_.begin() + static_cast<std::ptrdiff_t>(worst));
  }
}

Verification HypothesisVerifier::verify(const Pose2& map_T_laser,
                                        const std::vector<ReflectorDetection>& detections) {
  Verification v;
  v.map_T_laser = map_T_laser;
  if (associate(map_T_laser, detections, relocalization_.verify_coarse_gate) >= 3)
    refit(detections, v.map_T_laser);
  associate(v.map_T_laser, detections, relocalization_.verify_fine_gate);
  drop_unsupported_pairs(detections);
  v.matched = static_cast<int>(associations_.size());
  for (size_t k = 0; k < predicted_.size(); ++k) {
    if (predicted_[k].in_view && !predicted_matched_[k] &&
        predicted_[k].range <= relocalization_.missed_penalty_max_range &&
        !is_shadowed(map_, predicted_, k) && sight_.clear(map_, predicted_, k)) {
      ++v.missed;
    }
  }
  v.unexplained = static_cast<int>(detections.size()) - v.matched;
  v.score = v.matched - relocalization_.missed_penalty * v.missed -
            relocalization_.unexplained_penalty * v.unexplained;
  // The reported pose uses every fine association; the associations themselves stay as scored.
  Pose2 refined = v.map_T_laser;
  if (refit(detections, refined)) v.map_T_laser = refined;
  return v;
}

}  // namespace refloc
