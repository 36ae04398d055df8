#include "reflector_matcher/reflector_matcher.hpp"

#include "match_checks.hpp"
#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(TrackingAssociation, CorrectUnderPriorErrorOfTwentyCentimetresAndThreeDegrees) {
  std::mt19937 rng(11);
  const ReflectorMap map = testing::random_map(20, 40, 40, 1.0, rng);
  ReflectorMatcher matcher(map, MatcherConfig{});
  std::uniform_real_distribution<double> ux(0, 40), ua(-M_PI, M_PI);
  MatchResult result;
  int tracked = 0, all_seen_matched = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Pose2 truth{ux(rng), ux(rng), ua(rng)};
    const auto scan = testing::render_detections(map, truth, testing::SyntheticSensor{}, rng);
    if (scan.detections.size() < 3) continue;
    const double dir = ua(rng);
    PosePrior prior;
    prior.map_T_laser = Pose2{truth.x + 0.2 * std::cos(dir), truth.y + 0.2 * std::sin(dir),
                              truth.theta + (trial % 2 ? 3.0 : -3.0) * M_PI / 180.0};
    prior.covariance = Eigen::Vector3d(0.1 * 0.1, 0.1 * 0.1, std::pow(2.0 * M_PI / 180.0, 2)).asDiagonal();
    matcher.match(scan.detections, &prior, result);
    ASSERT_EQ(result.mode, MatchMode::kTracking);
    ASSERT_EQ(result.status, MatchStatus::kOk);
    ASSERT_TRUE(testing::all_matches_correct(result, scan, map));
    EXPECT_TRUE(approx_equal(result.map_T_laser, truth, 0.1, 1.0 * M_PI / 180.0))
        << result.map_T_laser.x - truth.x << " " << result.map_T_laser.y - truth.y << " "
        << result.map_T_laser.theta - truth.theta << " n=" << result.matches.size();
    ++tracked;
    all_seen_matched += result.matches.size() == scan.detections.size();
  }
  EXPECT_GT(tracked, 800);
  EXPECT_EQ(all_seen_matched, tracked);
}

TEST(TrackingAssociation, FallsBackToGlobalWhenThePriorIsFarOff) {
  std::mt19937 rng(12);
  const ReflectorMap map = testing::random_map(20, 40, 40, 1.0, rng);
  ReflectorMatcher matcher(map, MatcherConfig{});
  const Pose2 truth{20, 20, 0.5};
  const auto scan = testing::render_detections(map, truth, testing::SyntheticSensor{}, rng);
  ASSERT_GE(scan.detections.size(), 4u);
  PosePrior prior;
  prior.map_T_laser = Pose2{5, 35, -2.0};
  prior.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  MatchResult result;
  matcher.match(scan.detections, &prior, result);
  EXPECT_EQ(result.mode, MatchMode::kGlobal);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  EXPECT_TRUE(testing::all_matches_correct(result, scan, map));
  EXPECT_TRUE(approx_equal(result.map_T_laser, truth, 0.05, 0.01));
}

// Three reflectors, a confident prior 8 m away: tracking fails and the map fits the scan
// elsewhere on the bare minimum of pairs. One such scan is held back (AMBIGUOUS); the next scan
// that finds the same pose within the window is the fix; after the window it is held again.
TEST(TrackingAssociation, OverruleOfAPriorOnThreePairsIsAFixOnlyWhenTheNextScanRepeatsIt) {
  std::mt19937 rng(14);
  const ReflectorMap map = testing::map_from_points({{2.0, 0.0}, {5.5, 1.0}, {3.0, 4.0}});
  const Pose2 truth{3.5, 1.5, -0.35};
  testing::SyntheticSensor sensor;
  sensor.range_sigma = 0.002;
  const auto scan = testing::render_detections(map, truth, sensor, rng);
  ASSERT_EQ(scan.detections.size(), 3u);
  PosePrior prior;
  prior.map_T_laser = Pose2{11.5, 1.5, -0.35};
  prior.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  MatcherConfig config;
  ReflectorMatcher matcher(map, config);
  MatchResult result;
  matcher.match(scan.detections, &prior, result);
  EXPECT_EQ(result.status, MatchStatus::kAmbiguous);
  EXPECT_TRUE(result.matches.empty());
  EXPECT_TRUE(matcher.held_bare_overrule());
  matcher.match(scan.detections, &prior, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  EXPECT_FALSE(matcher.held_bare_overrule());
  EXPECT_TRUE(testing::all_matches_correct(result, scan, map));
  EXPECT_TRUE(approx_equal(result.map_T_laser, truth, 0.05, 0.02));

  matcher.match(scan.detections, &prior, result);  // confirmed once: a new overrule is held again
  EXPECT_EQ(result.status, MatchStatus::kAmbiguous);
  for (int k = 0; k < config.tracking.bare_overrule_confirm_scans; ++k) matcher.match({}, &prior, result);
  matcher.match(scan.detections, &prior, result);  // beyond the window
  EXPECT_EQ(result.status, MatchStatus::kAmbiguous);

  config.tracking.bare_overrule_confirm_scans = 0;
  ReflectorMatcher unchecked(map, config);
  unchecked.match(scan.detections, &prior, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  ReflectorMatcher without_prior(map, MatcherConfig{});
  without_prior.match(scan.detections, nullptr, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
}

TEST(TrackingAssociation, IgnoresASpuriousDetectionFarFromEveryReflector) {
  std::mt19937 rng(13);
  const ReflectorMap map = testing::random_map(20, 40, 40, 1.0, rng);
  ReflectorMatcher matcher(map, MatcherConfig{});
  const Pose2 truth{20, 20, 0.0};
  auto scan = testing::render_detections(map, truth, testing::SyntheticSensor{}, rng);
  ASSERT_GE(scan.detections.size(), 3u);
  ReflectorDetection ghost;
  ghost.laser_p_center = {0.5, 0.4};  // e.g. a shiny vest next to the robot
  scan.detections.push_back(ghost);
  scan.map_index.push_back(-1);
  PosePrior prior{truth, Eigen::Matrix3d::Identity() * 1e-4};
  MatchResult result;
  matcher.match(scan.detections, &prior, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  EXPECT_EQ(result.matches.size(), scan.detections.size() - 1);
  for (const auto& m : result.matches)
    EXPECT_NE(m.detection_index, static_cast<int>(scan.detections.size()) - 1);
}

// A rectangle of reflectors looks the same from its centre facing either way, so the map-wide
// search is AMBIGUOUS; two short walls hide two reflectors from a prior 0.3 m off (but not from
// the truth), so tracking from it fails. The prior then settles the choice when it admits one of
// the two poses alone, whichever the search ranked first.
TEST(TrackingAssociation, APriorThatAdmitsOneOfTheAmbiguousPosesSettlesIt) {
  std::mt19937 rng(15);
  ReflectorMap map = testing::map_from_points({{0.0, 0.0}, {10.0, 0.0}, {0.0, 6.0}, {10.0, 6.0}});
  map.occluders.push_back({"post west", {{4.0, 2.55}, {4.0, 2.75}}, false});
  map.occluders.push_back({"post east", {{6.0, 2.55}, {6.0, 2.75}}, false});
  const Pose2 truth{5.0, 3.0, M_PI / 2}, mirrored{5.0, 3.0, -M_PI / 2};
  testing::SyntheticSensor sensor;
  sensor.range_sigma = 0.002;
  const auto scan = testing::render_detections(map, truth, sensor, rng);
  ASSERT_EQ(scan.detections.size(), 4u);
  MatchResult result;
  ReflectorMatcher without_prior(map, MatcherConfig{});
  without_prior.match(scan.detections, nullptr, result);
  ASSERT_EQ(result.status, MatchStatus::kAmbiguous);

  const double sigma_theta = 5.0 * M_PI / 180.0;
  for (const Pose2& meant : {truth, mirrored}) {
    ReflectorMatcher matcher(map, MatcherConfig{});
    PosePrior prior;
    prior.map_T_laser = Pose2{5.0, 3.3, meant.theta};
    prior.covariance = Eigen::Vector3d(0.2 * 0.2, 0.2 * 0.2, sigma_theta * sigma_theta).asDiagonal();
    matcher.match(scan.detections, &prior, result);
    EXPECT_TRUE(matcher.tracking_association_failed());
    EXPECT_TRUE(matcher.prior_settled_ambiguity());
    EXPECT_EQ(result.status, MatchStatus::kOk);
    EXPECT_EQ(result.mode, MatchMode::kTracking);
    EXPECT_EQ(result.matches.size(), 4u);
    EXPECT_TRUE(approx_equal(result.map_T_laser, meant, 0.02, 0.01))
        << result.map_T_laser.x << " " << result.map_T_laser.y << " " << result.map_T_laser.theta;

    // A prior that admits both headings (or neither pose) leaves the scan AMBIGUOUS.
    prior.covariance(2, 2) = M_PI * M_PI;
    matcher.match(scan.detections, &prior, result);
    EXPECT_EQ(result.status, MatchStatus::kAmbiguous);
    EXPECT_FALSE(matcher.prior_settled_ambiguity());
    prior.covariance(2, 2) = sigma_theta * sigma_theta;
    prior.map_T_laser.x = 3.0;
    matcher.match(scan.detections, &prior, result);
    EXPECT_NE(result.status, MatchStatus::kOk);
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
