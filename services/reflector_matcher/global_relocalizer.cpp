#include "reflector_matcher/global_relocalizer.hpp"

#include "reflector_matcher/rigid_fit_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace refloc {
namespace {

constexpr std::array<std::array<int, 3>, 6> kPermutations = {
    {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};

}  // namespace

GlobalRelocalizer::GlobalRelocalizer(const ReflectorMap& map, const MapGrid& grid,
                                     const MapTriangleIndex& index,
                                     const RelocalizationConfig& relocalization,
                                     const SensorVisibilityConfig& sensor, int min_matches,
                                     const OccluderGrid* occluders)
    : map_(map),
      relocalization_(relocalization),
      min_matches_(min_matches),
      index_(index),
      verifier_(map, grid, sensor, relocalization, occluders) {}

std::array<double, 3> GlobalRelocalizer::side_tolerances(const std::vector<ReflectorDetection>& detections,
                                                         const std::array<int, 3>& det,
                                                         const SortedSides& s) const {
  const double base = relocalization_.side_tolerance;
  std::array<double, 3> tol = {base, base, base};
  if (relocalization_.side_tolerance_sigmas <= 0.0) return tol;
  for (size_t m = 0; m < 3; ++m) {
    // Side m joins the two vertices other than the one opposite it.
    const auto& a = detections[static_cast<size_t>(det[static_cast<size_t>((s.opposite[m] + 1) % 3)])];
    const auto& b = detections[static_cast<size_t>(det[static_cast<size_t>((s.opposite[m] + 2) % 3)])];
    const Eigen::Vector2d along = a.laser_p_center - b.laser_p_center;
    const double length = along.norm();
    if (length <= 0.0) continue;
    const Eigen::Vector2d u = along / length;
    const double variance = u.dot((a.covariance + b.covariance) * u);
    const double widened =
        std::sqrt(base * base + relocalization_.side_tolerance_sigmas *
                                    relocalization_.side_tolerance_sigmas * std::max(0.0, variance));
    tol[m] = std::max(base, std::min(relocalization_.max_side_tolerance, widened));  // never below base
  }
  return tol;
}

void GlobalRelocalizer::generate_hypotheses(const std::vector<ReflectorDetection>& detections) {
  hypotheses_.clear();
  nearest_.clear();
  for (size_t i = 0; i < detections.size(); ++i) nearest_.push_back(static_cast<int>(i));
  // Near detections are the most accurate and the most likely to be real reflectors.
  std::sort(nearest_.begin(), nearest_.end(), [&](int a, int b) {
    return detections[static_cast<size_t>(a)].laser_p_center.squaredNorm() <
           detections[static_cast<size_t>(b)].laser_p_center.squaredNorm();
  });
  if (static_cast<int>(nearest_.size()) > relocalization_.max_triple_detections) {
    nearest_.resize(static_cast<size_t>(relocalization_.max_triple_detections));
  }
  const double tol = relocalization_.side_tolerance;
  const double max_err2 = relocalization_.hypothesis_fit_max_error * relocalization_.hypothesis_fit_max_error;
  const size_t n = nearest_.size();
  // The cap counts the poses that may win; those only the widened tolerance found have a cap of
  // their own, so that they never crowd out the strict lookups of later triangles.
  int may_win = 0, rivals_only = 0;
  const auto full = [&] { return may_win >= relocalization_.max_hypotheses; };
  for (size_t i = 0; i < n && !full(); ++i) {
    for (size_t j = i + 1; j < n && !full(); ++j) {
      for (size_t k = j + 1; k < n && !full(); ++k) {
        const std::array<int, 3> det = {nearest_[i], nearest_[j], nearest_[k]};
        const std::array<Eigen::Vector2d, 3> laser_p = {
            detections[static_cast<size_t>(det[0])].laser_p_center,
            detections[static_cast<size_t>(det[1])].laser_p_center,
            detections[static_cast<size_t>(det[2])].laser_p_center};
        const SortedSides s = sorted_sides(laser_p);
        if (s.side[0] < relocalization_.min_triangle_side - tol) continue;
        const std::array<double, 3> side_tol = side_tolerances(detections, det, s);
        index_.for_each_candidate(s.side, side_tol, [&](const IndexedTriangle& tri) {
          // Sorted order fixes the correspondence unless sides are nearly equal (isosceles):
          // try every vertex assignment whose sides agree, and let the rigid fit decide
          // (a mirrored assignment cannot fit a rotation).
          for (const auto& perm : kPermutations) {
            if (full()) return;
            bool sides_agree = true, within_fixed = true;
            for (int m = 0; m < 3 && sides_agree; ++m) {
              const double error = std::abs(s.side[static_cast<size_t>(m)] -
                                            tri.side[static_cast<size_t>(perm[static_cast<size_t>(m)])]);
              sides_agree = error <= side_tol[static_cast<size_t>(m)];
              within_fixed = within_fixed && error <= tol;
            }
            if (!sides_agree) continue;
            RigidFit2d fit;
            std::array<Eigen::Vector2d, 3> map_p;
            for (size_t m = 0; m < 3; ++m) {
              map_p[m] = map_.reflectors[static_cast<size_t>(tri.opposite[static_cast<size_t>(perm[m])])]
                             .map_p_center;
              fit.add(laser_p[static_cast<size_t>(s.opposite[m])], map_p[m]);
            }
            Pose2 map_T_laser;
            if (!fit.solve(map_T_laser)) continue;
            bool fits = true;
            for (size_t m = 0; m < 3 && fits; ++m) {
              fits = (map_T_laser * laser_p[static_cast<size_t>(s.opposite[m])] - map_p[m]).squaredNorm() <=
                     max_err2;
            }
            if (!fits || (!within_fixed && rivals_only >= relocalization_.max_hypotheses)) continue;
            hypotheses_.push_back({map_T_laser, within_fixed});
            if (within_fixed)
              ++may_win;
            else
              ++rivals_only;
          }
        });
      }
    }
  }
}

void GlobalRelocalizer::remove_duplicate_hypotheses() {
  // Every triangle of a correct scan proposes nearly the same pose: verify it once. Poses are
  // binned at 5 cm / 0.5 deg; a pair split by a bin edge is merely verified twice.
  constexpr double kBinXy = 0.05, kBinTheta = 0.5 * M_PI / 180.0;
  keyed_.clear();
  for (size_t i = 0; i < hypotheses_.size(); ++i) {
    const Pose2& h = hypotheses_[i].map_T_laser;
    const auto bin = [](double v, double width) {
      return static_cast<uint64_t>(std::llround(v / width) & 0x1FFFFF);
    };
    keyed_.push_back({bin(h.x, kBinXy) | (bin(h.y, kBinXy) << 21) | (bin(h.theta, kBinTheta) << 42), i});
  }
  std::sort(keyed_.begin(), keyed_.end());
  unique_.clear();
  for (size_t k = 0; k < keyed_.size(); ++k) {
    const Hypothesis& h = hypotheses_[keyed_[k].second];
    if (k == 0 || keyed_[k].first != keyed_[k - 1].first)
      unique_.push_back(h);
    else
      unique_.back().may_win = unique_.back().may_win || h.may_win;  // one strict triangle suffices
  }
  hypotheses_.swap(unique_);
}

void GlobalRelocalizer::relocalize(const std::vector<ReflectorDetection>& detections, MatchResult& result) {
  result.mode = MatchMode::kGlobal;
  result.status = MatchStatus::kLost;
  result.matches.clear();
  result.hypothesis_score = 0.0;
  result.runner_up_score = 0.0;
  result.runner_up_map_T_laser = Pose2{};
  result.ndetections = static_cast<int>(detections.size());
  scored_.clear();
  best_associations_.clear();
  rivals_.clear();
  if (static_cast<int>(detections.size()) < min_matches_) return;

  generate_hypotheses(detections);
  remove_duplicate_hypotheses();
  double best_score = -1e300;
  int best_matched = 0;
  Pose2 best_pose;
  bool any_may_win = false;
  for (const Hypothesis& h : hypotheses_) {
    const Verification v = verifier_.verify(h.map_T_laser, detections);
    scored_.push_back({v.map_T_laser, v.score, v.matched});
    if (h.may_win && v.score > best_score) {
      any_may_win = true;
      best_score = v.score;
      best_matched = v.matched;
      best_pose = v.map_T_laser;
      best_associations_ = verifier_.associations();
    }
  }
  if (!any_may_win) return;

  // A substantially different pose rivals the best when it scores nearly as well, or when it
  // explains as many detections and loses only on a few unseen reflectors: unmapped racks
  // and people hide reflectors, so "not seen" is weak evidence.
  double runner_up = -1e300;
  const double ratio_margin =
      std::min((1.0 - relocalization_.ambiguity_ratio) * best_matched, relocalization_.ambiguity_max_margin);
  for (const Scored& s : scored_) {
    if (approx_equal(s.map_T_laser, best_pose, relocalization_.distinct_pose_distance,
                     relocalization_.distinct_pose_angle))
      continue;
    if (s.score > runner_up) {
      runner_up = s.score;
      result.runner_up_map_T_laser = s.map_T_laser;
    }
    const double margin = best_score - s.score;
    if (margin < ratio_margin ||
        (s.matched >= best_matched && margin < relocalization_.ambiguity_missed_margin))
      rivals_.push_back(s.map_T_laser);
  }
  result.map_T_laser = best_pose;
  result.hypothesis_score = best_score;
  result.runner_up_score = scored_.size() > 1 && runner_up > -1e300 ? runner_up : 0.0;
  if (!explains_enough(best_matched, best_score, detections.size())) return;
  fill_matches(result);
  result.status = rivals_.empty() ? MatchStatus::kOk : MatchStatus::kAmbiguous;
}

bool GlobalRelocalizer::explains_enough(int matched, double score, size_t ndetections) const {
  // Most detections of a real scan are reflectors: a pose that explains few of them is a
  // chance alignment (or the map has changed), not a fix.
  return matched >= min_matches_ &&
         matched >= relocalization_.min_explained_fraction * static_cast<double>(ndetections) &&
         score >= relocalization_.min_score;
}

void GlobalRelocalizer::fill_matches(MatchResult& result) const {
  result.matches.clear();
  for (const Association& a : best_associations_) {
    const MapReflector& r = map_.reflectors[static_cast<size_t>(a.map_index)];
    result.matches.push_back({a.detection_index, r.id, r.map_p_center, r.radius});
  }
}

bool GlobalRelocalizer::adopt_rival(const Pose2& rival, const std::vector<ReflectorDetection>& detections,
                                    MatchResult& result) {
  const Verification v = verifier_.verify(rival, detections);
  if (!explains_enough(v.matched, v.score, detections.size())) return false;
  best_associations_ = verifier_.associations();
  result.runner_up_map_T_laser = result.map_T_laser;
  result.runner_up_score = result.hypothesis_score;
  result.map_T_laser = v.map_T_laser;
  result.hypothesis_score = v.score;
  fill_matches(result);
  result.status = MatchStatus::kOk;
  return true;
}

}  // namespace refloc
