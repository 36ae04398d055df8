#include "reflector_matcher/reflector_matcher.hpp"

#include "common/angles.hpp"
#include "common/se2.hpp"

#include <Eigen/Cholesky>

namespace refloc {
namespace {

/// chi-square, 3 degrees of freedom, 99.9 %: the prior's region in (x, y, theta).
constexpr double kPriorGateChi2 = 16.27;

bool inside_prior_gate(const Pose2& map_T_laser, const PosePrior& prior,
                       const Eigen::LDLT<Eigen::Matrix3d>& covariance) {
  const Eigen::Vector3d e(map_T_laser.x - prior.map_T_laser.x, map_T_laser.y - prior.map_T_laser.y,
                          wrap_angle(map_T_laser.theta - prior.map_T_laser.theta));
  return e.dot(covariance.solve(e)) <= kPriorGateChi2;
}

}  // namespace

ReflectorMatcher::ReflectorMatcher(ReflectorMap map, const MatcherConfig& config)
    : map_(std::move(map)),
      config_(config),
      grid_(map_, 0.5 * config.sensor.max_range),
      occluders_(map_.occluders) {
  if (config_.mode == MatcherMode::kPaper) {
    paper_ = std::make_unique<PaperTriangleMatcher>(
        map_, config_.paper, config_.relocalization.max_triangle_side,
        static_cast<size_t>(config_.relocalization.max_index_triangles), config_.min_matches);
    return;
  }
  index_ = std::make_unique<MapTriangleIndex>(
      map_, config_.relocalization.side_tolerance, config_.relocalization.min_triangle_side,
      config_.relocalization.max_triangle_side,
      static_cast<size_t>(config_.relocalization.max_index_triangles));
  relocalizer_ = std::make_unique<GlobalRelocalizer>(map_, grid_, *index_, config_.relocalization,
                                                     config_.sensor, config_.min_matches, &occluders_);
  tracker_ = std::make_unique<TrackingAssociator>(map_, grid_, config_.tracking, config_.sensor,
                                                  config_.relocalization, config_.min_matches, &occluders_);
}

size_t ReflectorMatcher::indexed_triangles() const {
  return paper_ ? paper_->map_triangles() : index_->size();
}

void ReflectorMatcher::match(const std::vector<ReflectorDetection>& detections, const PosePrior* prior,
                             MatchResult& result) {
  if (paper_) {
    paper_->match(detections, result);
    return;
  }
  if (scans_since_overrule_ >= 0) ++scans_since_overrule_;
  prior_settled_ambiguity_ = false;
  tracking_association_failed_ = false;
  if (prior == nullptr || !tracker_->associate(detections, *prior, result)) {
    relocalizer_->relocalize(detections, result);
    if (prior == nullptr) return;
    tracking_association_failed_ = true;
    decide_with_prior(*prior, detections, result);
    if (result.mode == MatchMode::kGlobal) confirm_bare_overrule(*prior, result);
    return;
  }
  const int unexplained = result.ndetections - static_cast<int>(result.matches.size());
  if (unexplained <= config_.tracking.max_unexplained &&
      result.hypothesis_score >= config_.tracking.min_score)
    return;
  // A weak association (distractors, hidden reflectors, or a prior that is off) is checked by the
  // map-wide search, which owes nothing to the prior.
  std::swap(tracked_, result);
  relocalizer_->relocalize(detections, result);
  const bool global_ok = result.status == MatchStatus::kOk;
  if (global_ok &&
      !approx_equal(result.map_T_laser, tracked_.map_T_laser, config_.relocalization.distinct_pose_distance,
                    config_.relocalization.distinct_pose_angle)) {
    // The map alone points elsewhere: the prior may be wrong (kidnapped robot, odometry jump)
    // or the map-wide search fooled by a weak scene; scores cannot tell which here (unmapped
    // racks make "unseen" reflectors common), so no fix. Without fixes POSE ages, the prior
    // goes, and relocalization starts from the map alone.
    result.status = MatchStatus::kAmbiguous;
    result.runner_up_score = tracked_.hypothesis_score;
    result.matches.clear();
    return;
  }
  // The map agrees, or alone cannot decide (symmetric layouts are where tracking earns its keep):
  // keep the tracked association if it explains as much of the scan as a global OK must and,
  // when it rests on the bare minimum of pairs, weak and unconfirmed, all of it: three wrong
  // pairs next to a wrong prior leave the real reflectors in view unexplained.
  const auto tracked_matched = static_cast<int>(tracked_.matches.size());
  const bool bare_unconfirmed = !global_ok && tracked_matched <= config_.min_matches &&
                                tracked_.hypothesis_score < config_.tracking.min_score;
  if (tracked_matched < config_.relocalization.min_explained_fraction * tracked_.ndetections ||
      (bare_unconfirmed && tracked_matched < tracked_.ndetections)) {
    result.mode = MatchMode::kTracking;
    result.status = MatchStatus::kLost;
    result.matches.clear();
    return;
  }
  std::swap(tracked_, result);
}

void ReflectorMatcher::decide_with_prior(const PosePrior& prior,
                                         const std::vector<ReflectorDetection>& detections,
                                         MatchResult& result) {
  // Tracking from a wide prior (a user's INITIAL_POSE, 0.2 m / 5 deg) can fail where a
  // distractor sits beside a reflector; the map-wide search then knows nothing of the prior and
  // may be AMBIGUOUS between the true pose and one metres away, scan after scan (web_console's
  // browser test, once in CI). The prior is independent evidence: it settles the choice when it
  // admits exactly one of the hypotheses, the best or a rival.
  if (result.matches.empty()) return;
  const Eigen::LDLT<Eigen::Matrix3d> covariance(floored_prior_covariance(prior, config_.tracking));
  const bool best_inside = inside_prior_gate(result.map_T_laser, prior, covariance);
  if (result.status == MatchStatus::kOk) {
    if (best_inside) result.mode = MatchMode::kTracking;  // the map-wide search confirms the prior
    return;
  }
  const Pose2* admitted_rival = nullptr;
  for (const Pose2& rival : relocalizer_->rivals()) {
    if (!inside_prior_gate(rival, prior, covariance)) continue;
    if (best_inside || admitted_rival != nullptr) return;  // the prior admits two: still ambiguous
    admitted_rival = &rival;
  }
  if (!best_inside &&
      (admitted_rival == nullptr || !relocalizer_->adopt_rival(*admitted_rival, detections, result)))
    return;
  result.status = MatchStatus::kOk;
  result.mode = MatchMode::kTracking;
  prior_settled_ambiguity_ = true;
}

void ReflectorMatcher::confirm_bare_overrule(const PosePrior& prior, MatchResult& result) {
  const int window = config_.tracking.bare_overrule_confirm_scans;
  const RelocalizationConfig& r = config_.relocalization;
  if (window <= 0 || result.status != MatchStatus::kOk ||
      static_cast<int>(result.matches.size()) > config_.min_matches ||
      approx_equal(result.map_T_laser, prior.map_T_laser, r.distinct_pose_distance, r.distinct_pose_angle))
    return;
  // Measured in the demo hall with reflectors moved (reflector_matcher README): one scan whose
  // tracking failed relocalized OK on three pairs 15 m from a correct prior.
  if (scans_since_overrule_ >= 0 && scans_since_overrule_ <= window &&
      approx_equal(result.map_T_laser, unconfirmed_overrule_, r.distinct_pose_distance,
                   r.distinct_pose_angle)) {
    scans_since_overrule_ = -1;
    return;
  }
  unconfirmed_overrule_ = result.map_T_laser;
  scans_since_overrule_ = 0;
  result.status = MatchStatus::kAmbiguous;
  result.runner_up_map_T_laser = prior.map_T_laser;
  result.matches.clear();
}

}  // namespace refloc
