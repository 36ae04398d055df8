// The driving survey end to end on a rendered drive of the demo hall (drive_rendered.hpp):
// cold start, no map, no ids, odometry 1 % long and drifting in heading, the LMS100 with a
// +20 mm range offset. ~14 s of driving along the lower aisle at 10 Hz.

#include "drive_survey.hpp"
#include "drive_map_comparison.hpp"
#include "drive_rendered.hpp"
#include "drive_report.hpp"

#include "common/reflector_map.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using testing::RenderedDrive;

const RenderedDrive& drive() { return testing::lower_aisle_drive(); }

const DriveSurveyResult& survey() {
  static const DriveSurveyResult r =
      run_drive_survey(drive().scans, Pose2{0.30, 0.0, 0.0}, OdometryNoise{},
                       drive().true_map_T_robot.front(), {}, DriveSurveyConfig{});
  return r;
}

TEST(DriveSurvey, MapsEachReflectorOfARenderedDriveOnceAndNoDistractor) {
  const ReflectorMap truth = load_reflector_map(testing::kDemoMap);
  const MapComparison c = compare_maps(surveyed_map(survey(), survey().occluders, "test", 0.06), truth);
  ASSERT_TRUE(c.aligned);
  EXPECT_TRUE(c.extra_map_ids.empty()) << comparison_text(c);
  // ~11 m along the lower aisle: the south wall's reflectors and those on the racks' ends and
  // south faces; the tape on rack 1's south face is seen (and refused: it is on a surface).
  EXPECT_GE(c.matched.size(), 7u) << comparison_text(c);
  const auto tape = std::find_if(
      survey().rejected.begin(), survey().rejected.end(),
      [](const RejectedTrack& t) { return (t.map_p - Eigen::Vector2d(6.55, 5.18)).norm() < 0.1; });
  ASSERT_NE(tape, survey().rejected.end());
  EXPECT_NE(tape->reason.find("on the surface"), std::string::npos) << tape->reason;
  EXPECT_EQ(survey().reflectors.size(), c.matched.size());
}

TEST(DriveSurvey, SurveyedPositionsAreWithinMillimetresOfTheTruth) {
  const ReflectorMap map = surveyed_map(survey(), survey().occluders, "test", 0.06);
  const ReflectorMap truth = load_reflector_map(testing::kDemoMap);
  const MapComparison aligned = compare_maps(map, truth);
  EXPECT_LT(aligned.rms, 0.006) << comparison_text(aligned);
  EXPECT_LT(aligned.worst, 0.010) << comparison_text(aligned);
  EXPECT_EQ(aligned.within_3_sigma, static_cast<int>(aligned.matched.size())) << comparison_text(aligned);
  // Without the alignment: the frame is the first scan's pose, the start pose given (the true
  // one here), known only as well as one scan's reflectors place it.
  MapComparisonOptions in_place;
  in_place.align = false;
  EXPECT_LT(compare_maps(map, truth, in_place).worst, 0.03);
}

TEST(DriveSurvey, EstimatesTheRangeOffsetOfTheSensor) {
  EXPECT_NEAR(survey().range_bias, 0.02, 0.003);
  EXPECT_GT(survey().range_bias_sigma, 0.0);
  EXPECT_LT(survey().range_bias_sigma, 0.003);
}

TEST(DriveSurvey, KeepsThePosesOnTheTruthWhileOdometryAloneDrifts) {
  const RenderedDrive& d = drive();
  const DriveSurveyResult& r = survey();
  ASSERT_EQ(r.map_T_robot.size(), d.scans.size());
  const Pose2 start = d.true_map_T_robot.front();
  const Pose2 dead_reckoned = start * d.scans.front().odom_T_robot.inverse() * d.scans.back().odom_T_robot;
  const Pose2& truth = d.true_map_T_robot.back();
  EXPECT_GT((dead_reckoned.translation() - truth.translation()).norm(), 0.1);
  double worst = 0.0;
  for (size_t k = 0; k < r.map_T_robot.size(); ++k)
    worst = std::max(worst, (r.map_T_robot[k].translation() - d.true_map_T_robot[k].translation()).norm());
  EXPECT_LT(worst, 0.02);
  EXPECT_EQ(r.map_T_robot.front().x, start.x);  // the first pose holds the frame
}

TEST(DriveSurvey, TracesTheSouthWallAsAnOccluder) {
  bool south_wall = false;
  for (const MapOccluder& o : survey().occluders) {
    const Eigen::Vector2d a = o.map_points.front(), b = o.map_points.back();
    if (std::abs(a.y()) < 0.05 && std::abs(b.y()) < 0.05 && std::abs(a.x() - b.x()) > 8.0) south_wall = true;
  }
  EXPECT_TRUE(south_wall);
}

TEST(DriveSurvey, AnchorsMoveTheFrameOntoTheirCoordinates) {
  // Survey frame = the start pose's; anchors named by where they are in it, given in a frame
  // shifted by (10, 20) and turned by 90 deg.
  const Pose2 given_T_truth{10.0, 20.0, M_PI / 2};
  const ReflectorMap truth = load_reflector_map(testing::kDemoMap);
  std::vector<SurveyAnchor> anchors;
  for (int id : {2, 4, 18}) {  // south wall and rack 2, all seen from the lower aisle
    const Eigen::Vector2d p = truth.reflectors[static_cast<size_t>(truth.index_of(id))].map_p_center;
    anchors.push_back({id, given_T_truth * p, p});
  }
  const DriveSurveyResult r =
      run_drive_survey(drive().scans, Pose2{0.30, 0.0, 0.0}, OdometryNoise{},
                       drive().true_map_T_robot.front(), anchors, DriveSurveyConfig{});
  for (const SurveyAnchor& a : anchors) {
    const auto it = std::find_if(r.reflectors.begin(), r.reflectors.end(),
                                 [&](const SurveyedReflector& s) { return s.id == a.id; });
    ASSERT_NE(it, r.reflectors.end()) << "anchor id " << a.id;
    EXPECT_TRUE(it->anchor);
    EXPECT_LT((it->map_p - a.map_p).norm(), 1e-9);
  }
  // Every other reflector lands where the truth, moved the same way, is.
  for (const SurveyedReflector& s : r.reflectors) {
    double nearest = 1e9;
    for (const MapReflector& t : truth.reflectors)
      nearest = std::min(nearest, (given_T_truth * t.map_p_center - s.map_p).norm());
    EXPECT_LT(nearest, 0.015) << "id " << s.id;
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
