#include "reflector_matcher/reflector_matcher.hpp"

#include "match_checks.hpp"
#include "synthetic_detections.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

MatcherConfig paper_config() {
  MatcherConfig c;
  c.mode = MatcherMode::kPaper;
  return c;
}

ReflectorMap irregular_map() {
  return testing::map_from_points({{0, 0}, {7.3, 0.4}, {3.1, 5.2}, {9.8, 6.7}, {-2.5, 8.1}, {5.5, 11.3}});
}

TEST(PaperTriangleMatcher, FindsTheRightCorrespondencesWithAllReflectorsInView) {
  const ReflectorMap map = irregular_map();
  ReflectorMatcher matcher(map, paper_config());
  EXPECT_EQ(matcher.indexed_triangles(), 20u);  // C(6, 3)
  std::mt19937 rng(18);
  const Pose2 truth{3.0, 4.0, 0.7};
  testing::SyntheticSensor sensor;
  sensor.field_of_view = 2 * M_PI;
  const auto scan = testing::render_detections(map, truth, sensor, rng);
  ASSERT_EQ(scan.detections.size(), 6u);
  MatchResult result;
  matcher.match(scan.detections, nullptr, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  EXPECT_EQ(result.mode, MatchMode::kGlobal);
  EXPECT_EQ(result.matches.size(), 6u);
  EXPECT_TRUE(testing::all_matches_correct(result, scan, map));
  EXPECT_TRUE(approx_equal(result.map_T_laser, truth, 0.03, 0.005));
}

TEST(PaperTriangleMatcher, RightCorrespondencesOnRandomPoses) {
  const ReflectorMap map = irregular_map();
  ReflectorMatcher matcher(map, paper_config());
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> ux(-2, 10), uy(-1, 11), ua(-M_PI, M_PI);
  MatchResult result;
  int seen3 = 0, right = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Pose2 truth{ux(rng), uy(rng), ua(rng)};
    const auto scan = testing::render_detections(map, truth, testing::SyntheticSensor{}, rng);
    if (scan.detections.size() < 3) continue;
    ++seen3;
    matcher.match(scan.detections, nullptr, result);
    right += result.status == MatchStatus::kOk && testing::all_matches_correct(result, scan, map) &&
             result.matches.size() == scan.detections.size();
  }
  std::printf("paper matcher: %d of %d scans with >= 3 reflectors fully and correctly matched\n", right,
              seen3);
  EXPECT_GE(right, seen3 * 9 / 10);
}

TEST(PaperTriangleMatcher, MatchesAMirroredScanBecauseItsSignatureIsMirrorInvariant) {
  // The baseline's known weakness, kept on purpose: the default mode rejects this scan.
  const ReflectorMap map = irregular_map();
  std::mt19937 rng(20);
  testing::SyntheticSensor sensor;
  sensor.field_of_view = 2 * M_PI;
  sensor.range_sigma = sensor.bearing_sigma = 0.0;
  auto scan = testing::render_detections(map, Pose2{3.0, 4.0, 0.7}, sensor, rng);
  for (auto& d : scan.detections) d.laser_p_center.y() = -d.laser_p_center.y();
  MatchResult result;
  ReflectorMatcher paper(map, paper_config());
  paper.match(scan.detections, nullptr, result);
  EXPECT_EQ(result.status, MatchStatus::kOk);
  ReflectorMatcher verified(map, MatcherConfig{});
  verified.match(scan.detections, nullptr, result);
  EXPECT_NE(result.status, MatchStatus::kOk);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
