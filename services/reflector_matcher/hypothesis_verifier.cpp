#include "reflector_matcher/hypothesis_verifier.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

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
    remove_association(worst);
  }
}

void HypothesisVerifier::remove_association(size_t index) {
  for (size_t k = 0; k < predicted_.size(); ++k) {
    if (predicted_[k].map_index == associations_[index].map_index) predicted_matched_[k] = 0;
  }
  detection_used_[static_cast<size_t>(associations_[index].detection_index)] = 0;
  associations_.erase(associations_.begin() + static_cast<std::ptrdiff_t>(index));
}

double chi_square_bound(int dof, double sigmas) {
  const double k = static_cast<double>(std::max(dof, 1));
  const double a = 2.0 / (9.0 * k);
  const double c = 1.0 - a + sigmas * std::sqrt(a);
  return k * c * c * c;
}

double HypothesisVerifier::fit_chi2(const std::vector<ReflectorDetection>& detections,
                                    const Pose2& map_T_laser) const {
  const Eigen::Matrix2d rotation = map_T_laser.rotation();
  double chi2 = 0.0;
  for (size_t i = 0; i < associations_.size(); ++i) {
    const ReflectorDetection& d = detections[static_cast<size_t>(associations_[i].detection_index)];
    const MapReflector& r = map_.reflectors[static_cast<size_t>(associations_[i].map_index)];
    const Eigen::Matrix2d map_cov =
        r.map_cov_center ? *r.map_cov_center
                         : Eigen::Matrix2d(relocalization_.map_sigma * relocalization_.map_sigma *
                                           Eigen::Matrix2d::Identity());
    const Eigen::Vector2d line_of_sight = rotation * d.laser_p_center.normalized();
    const double bias2 = relocalization_.range_bias_sigma * relocalization_.range_bias_sigma;
    const Eigen::Matrix2d cov = rotation * d.covariance * rotation.transpose() + map_cov +
                                bias2 * line_of_sight * line_of_sight.transpose();
    const Eigen::Vector2d e = map_T_laser * d.laser_p_center - r.map_p_center;
    const double term = e.dot(cov.ldlt().solve(e));
    if (!std::isfinite(term)) continue;
    chi2 += term;
  }
  return chi2;
}

int HypothesisVerifier::drop_inconsistent_pairs(const std::vector<ReflectorDetection>& detections,
                                                Pose2& map_T_laser) {
  // Each pair can lie within the fine gate while together they fit no rigid pose: two of three
  // reflectors moved by 0.3 m, matched as if in place, leave ~0.1 m residuals that the
  // detections' centimetre covariances call impossible. The test is the fit's chi-square
  // against its dof = 2 x pairs - 3.
  if (relocalization_.fit_consistency_sigmas <= 0.0) return 0;
  int dropped = 0;
  while (associations_.size() >= 3) {
    const double chi2 = fit_chi2(detections, map_T_laser);
    const int dof = 2 * static_cast<int>(associations_.size()) - 3;
    if (chi2 <= chi_square_bound(dof, relocalization_.fit_consistency_sigmas)) return dropped;
    if (associations_.size() == 3) {
      dropped += 3;
      while (!associations_.empty()) remove_association(associations_.size() - 1);
      return dropped;
    }
    // Drop the pair whose absence leaves the most consistent fit (the largest term of the
    // all-pairs fit may belong to a good pair the bad one pulled away).
    size_t drop = 0;
    double best_chi2 = std::numeric_limits<double>::infinity();
    all_pairs_ = associations_;  // a member: no allocation per scan once it has grown
    for (size_t i = 0; i < all_pairs_.size(); ++i) {
      associations_ = all_pairs_;
      associations_.erase(associations_.begin() + static_cast<std::ptrdiff_t>(i));
      Pose2 pose = map_T_laser;
      if (!refit(detections, pose)) continue;
      const double c = fit_chi2(detections, pose);
      if (c < best_chi2) best_chi2 = c, drop = i;
    }
    associations_ = all_pairs_;
    remove_association(drop);
    ++dropped;
    refit(detections, map_T_laser);
  }
  return dropped;
}

Verification HypothesisVerifier::verify(const Pose2& map_T_laser,
                                        const std::vector<ReflectorDetection>& detections) {
  Verification v;
  v.map_T_laser = map_T_laser;
  if (associate(map_T_laser, detections, relocalization_.verify_coarse_gate) >= 3)
    refit(detections, v.map_T_laser);
  associate(v.map_T_laser, detections, relocalization_.verify_fine_gate);
  drop_unsupported_pairs(detections);
  Pose2 fitted = v.map_T_laser;
  if (refit(detections, fitted)) v.inconsistent = drop_inconsistent_pairs(detections, fitted);
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
