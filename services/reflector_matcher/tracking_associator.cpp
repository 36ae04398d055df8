#include "reflector_matcher/tracking_associator.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace refloc {

Eigen::Matrix3d floored_prior_covariance(const PosePrior& prior, const TrackingConfig& tracking) {
  Eigen::Matrix3d cov = prior.covariance;
  const double min_var_xy = tracking.prior_min_sigma_xy * tracking.prior_min_sigma_xy;
  const double min_var_theta = tracking.prior_min_sigma_theta * tracking.prior_min_sigma_theta;
  cov(0, 0) = std::max(cov(0, 0), min_var_xy);
  cov(1, 1) = std::max(cov(1, 1), min_var_xy);
  cov(2, 2) = std::max(cov(2, 2), min_var_theta);
  return cov;
}

TrackingAssociator::TrackingAssociator(const ReflectorMap& map, const MapGrid& grid,
                                       const TrackingConfig& tracking, const SensorVisibilityConfig& sensor,
                                       const RelocalizationConfig& relocalization, int min_matches,
                                       const OccluderGrid* occluders)
    : map_(map),
      grid_(grid),
      occluders_(occluders),
      tracking_(tracking),
      sensor_(sensor),
      min_matches_(min_matches),
      refit_verifier_(map, grid, sensor, relocalization, occluders) {}

bool TrackingAssociator::associate(const std::vector<ReflectorDetection>& detections, const PosePrior& prior,
                                   MatchResult& result) {
  result.mode = MatchMode::kTracking;
  result.status = MatchStatus::kLost;
  result.matches.clear();
  result.hypothesis_score = 0.0;
  result.runner_up_score = 0.0;
  result.map_T_laser = prior.map_T_laser;
  result.ndetections = static_cast<int>(detections.size());

  const Eigen::Matrix3d prior_cov = floored_prior_covariance(prior, tracking_);

  // The prior's 3-sigma position error widens the search beyond the nominal view.
  const double margin = 3.0 * std::sqrt(std::max(prior_cov(0, 0), prior_cov(1, 1))) +
                        3.0 * std::sqrt(prior_cov(2, 2)) * sensor_.max_range;
  predict_reflectors(map_, grid_, prior.map_T_laser, sensor_, margin, scratch_, predicted_);
  sight_.reset(occluders_, prior.map_T_laser.translation(), predicted_.size());

  const double c = std::cos(prior.map_T_laser.theta), s = std::sin(prior.map_T_laser.theta);
  Eigen::Matrix2d laser_R_map_derivative;  // d(R^T)/d theta
  laser_R_map_derivative << -s, c, -c, -s;
  Eigen::Matrix2d laser_R_map;
  laser_R_map << c, s, -s, c;
  const double min_det_var = tracking_.detection_min_sigma * tracking_.detection_min_sigma;

  candidates_.clear();
  for (size_t k = 0; k < predicted_.size(); ++k) {
    const Eigen::Vector2d map_p = map_.reflectors[static_cast<size_t>(predicted_[k].map_index)].map_p_center;
    // laser_p = R^T (map_p - t): Jacobian w.r.t. (x, y, theta) of map_T_laser.
    Eigen::Matrix<double, 2, 3> j;
    j.leftCols<2>() = -laser_R_map;
    j.col(2) = laser_R_map_derivative * (map_p - prior.map_T_laser.translation());
    const Eigen::Matrix2d prior_part = j * prior_cov * j.transpose();
    for (size_t d = 0; d < detections.size(); ++d) {
      Eigen::Matrix2d cov = prior_part + detections[d].covariance;
      cov(0, 0) += min_det_var;
      cov(1, 1) += min_det_var;
      const Eigen::Vector2d e = detections[d].laser_p_center - predicted_[k].laser_p;
      const double m2 = e.dot(cov.inverse() * e);
      if (m2 <= tracking_.gate_chi2) candidates_.push_back({m2, static_cast<int>(k), static_cast<int>(d)});
    }
  }
  std::sort(candidates_.begin(), candidates_.end(),
            [](const Candidate& a, const Candidate& b) { return a.mahalanobis2 < b.mahalanobis2; });
  predicted_used_.assign(predicted_.size(), 0);
  detection_used_.assign(detections.size(), 0);
  RigidFit2d fit;
  for (const Candidate& cand : candidates_) {
    const auto k = static_cast<size_t>(cand.predicted_index), d = static_cast<size_t>(cand.detection_index);
    if (predicted_used_[k] || detection_used_[d] || sight_.hidden(map_, predicted_, k)) continue;
    predicted_used_[k] = detection_used_[d] = 1;
    fit.add(detections[d].laser_p_center,
            map_.reflectors[static_cast<size_t>(predicted_[k].map_index)].map_p_center);
  }
  if (fit.count() < min_matches_) return false;
  Pose2 refined;
  if (!fit.solve(refined)) return false;

  // Greedy pairs under a wide gate can swap neighbours; the majority is right, so the refitted
  // pose is close: associate again with the verifier's coarse-then-fine Euclidean gates.
  const Verification v = refit_verifier_.verify(refined, detections);
  if (v.matched < min_matches_) return false;
  RigidFit2d final_fit;
  for (const Association& a : refit_verifier_.associations()) {
    const MapReflector& r = map_.reflectors[static_cast<size_t>(a.map_index)];
    result.matches.push_back({a.detection_index, r.id, r.map_p_center, r.radius});
    final_fit.add(detections[static_cast<size_t>(a.detection_index)].laser_p_center, r.map_p_center);
  }
  final_fit.solve(result.map_T_laser);
  result.hypothesis_score = v.score;
  result.status = MatchStatus::kOk;
  return true;
}

}  // namespace refloc
