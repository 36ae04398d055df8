// The verifier's fit consistency test: pairs that each lie within the fine gate but together
// fit no rigid pose (reflectors moved since the map was made) are not a match.

#include "reflector_matcher/hypothesis_verifier.hpp"
#include "reflector_matcher/reflector_matcher.hpp"

#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::SyntheticSensor;

ReflectorMap three_reflectors() {
  ReflectorMap map;
  map.reflectors = {
      {1, {4.0, 0.0}, 0.06, "", {}}, {2, {0.0, 5.0}, 0.06, "", {}}, {3, {-3.0, -4.0}, 0.06, "", {}}};
  return map;
}

/// Detections of the map's reflectors from the origin, with reflectors moved in the world.
std::vector<ReflectorDetection> detections_of(const std::vector<Eigen::Vector2d>& world) {
  std::vector<ReflectorDetection> detections;
  for (const Eigen::Vector2d& p : world) {
    ReflectorDetection d;
    d.laser_p_center = p;
    d.range = p.norm();
    d.bearing = std::atan2(p.y(), p.x());
    d.covariance = testing::polar_covariance(d.range, d.bearing, 0.012, 0.002);
    detections.push_back(d);
  }
  return detections;
}

TEST(ChiSquareBound, MatchesTheExactQuantiles) {
  // Chi-square quantiles at P = 0.99977 (3.5 sigma), interpolated in log(1 - P) between the
  // tabulated 0.999 and 0.9999 ones: dof 3 -> 19.3, dof 7 -> 27.8.
  EXPECT_NEAR(chi_square_bound(3, 3.5), 19.3, 0.7);
  EXPECT_NEAR(chi_square_bound(7, 3.5), 27.8, 0.6);
  EXPECT_NEAR(chi_square_bound(20, 0.0), 20.0 * std::pow(1.0 - 2.0 / 180.0, 3), 1e-9);
}

TEST(FitConsistency, ThreePairsWithTwoReflectorsMovedByThirtyCentimetresExplainNothing) {
  // The demo hall at (18.29, 2.0) facing north, reflectors 4 and 14 moved 0.3 m along their
  // walls: the stack matched [19, 4, 14] as an OK fix (the best rigid fit spreads the moves
  // over the three pairs, each within the 0.15 m fine gate).
  ReflectorMap map;
  map.reflectors = {
      {19, {15.08, 6.0}, 0.06, "", {}}, {4, {13.4, 0.1}, 0.06, "", {}}, {14, {19.9, 7.9}, 0.06, "", {}}};
  const MapGrid grid(map, 10.0);
  const Pose2 map_T_laser{18.29, 2.0, M_PI / 2};
  const Pose2 laser_T_map = map_T_laser.inverse();
  const auto moved =
      detections_of({laser_T_map * Eigen::Vector2d(15.08, 6.0), laser_T_map * Eigen::Vector2d(13.7, 0.1),
                     laser_T_map * Eigen::Vector2d(19.9, 8.2)});
  RelocalizationConfig off;
  off.fit_consistency_sigmas = 0.0;
  HypothesisVerifier without(map, grid, SensorVisibilityConfig{}, off);
  ASSERT_EQ(without.verify(map_T_laser, moved).matched, 3) << "the case the test is for";

  HypothesisVerifier verifier(map, grid, SensorVisibilityConfig{}, RelocalizationConfig{});
  const Verification v = verifier.verify(map_T_laser, moved);
  EXPECT_EQ(v.matched, 0);
  EXPECT_EQ(v.inconsistent, 3);

  const auto in_place =
      detections_of({laser_T_map * Eigen::Vector2d(15.09, 6.01), laser_T_map * Eigen::Vector2d(13.39, 0.1),
                     laser_T_map * Eigen::Vector2d(19.9, 7.91)});
  const Verification kept = verifier.verify(map_T_laser, in_place);
  EXPECT_EQ(kept.matched, 3);
  EXPECT_EQ(kept.inconsistent, 0);
}

TEST(FitConsistency, ARangeBiasOfThirtyMillimetresIsNotAnInconsistency) {
  // The LMS100 may read every range up to 30 mm long; pose_solver, not the matcher, takes it out.
  const ReflectorMap map = three_reflectors();
  const MapGrid grid(map, 10.0);
  HypothesisVerifier verifier(map, grid, SensorVisibilityConfig{}, RelocalizationConfig{});
  std::vector<Eigen::Vector2d> long_ranges;
  for (const MapReflector& r : map.reflectors)
    long_ranges.push_back(r.map_p_center * (1.0 + 0.03 / r.map_p_center.norm()));
  EXPECT_EQ(verifier.verify(Pose2{}, detections_of(long_ranges)).matched, 3);
}

TEST(FitConsistency, WithFourPairsTheMovedOneIsDroppedAndTheRestKept) {
  ReflectorMap map = three_reflectors();
  map.reflectors.push_back({4, {6.0, 6.0}, 0.06, "", {}});
  const MapGrid grid(map, 10.0);
  HypothesisVerifier verifier(map, grid, SensorVisibilityConfig{}, RelocalizationConfig{});
  // Reflector 4 moved by 0.12 m: inside the fine gate, and too little for the 0.15 m
  // unsupported-pair rule to catch once the refit has bent towards it.
  const auto scan = detections_of({{4.0, 0.0}, {0.0, 5.0}, {-3.0, -4.0}, {6.12, 6.0}});
  const Verification v = verifier.verify(Pose2{}, scan);
  EXPECT_EQ(v.matched, 3);
  EXPECT_EQ(v.inconsistent, 1);
  for (const Association& a : verifier.associations()) EXPECT_NE(a.map_index, 3);
}

TEST(FitConsistency, NoFewerOkFixesOverAThousandRandomPoses) {
  std::mt19937 rng(11);
  const ReflectorMap map = testing::random_map(20, 40, 40, 1.0, rng);
  MatcherConfig off;
  off.relocalization.fit_consistency_sigmas = 0.0;
  ReflectorMatcher with_test(map, MatcherConfig{});
  ReflectorMatcher without_test(map, off);
  MatchResult result;
  int ok_with = 0, ok_without = 0;
  std::uniform_real_distribution<double> ux(0, 40), ua(-M_PI, M_PI);
  for (int trial = 0; trial < 1000; ++trial) {
    const Pose2 truth{ux(rng), ux(rng), ua(rng)};
    const auto scan = testing::render_detections(map, truth, SyntheticSensor{}, rng);
    with_test.match(scan.detections, nullptr, result);
    ok_with += result.status == MatchStatus::kOk;
    without_test.match(scan.detections, nullptr, result);
    ok_without += result.status == MatchStatus::kOk;
  }
  std::printf("OK fixes over 1000 random poses: %d with the consistency test, %d without\n", ok_with,
              ok_without);
  EXPECT_GE(ok_with, ok_without * 99 / 100);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
