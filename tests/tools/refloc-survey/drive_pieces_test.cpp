// The driving survey's pieces on data with a known answer: the track statistics, the batch
// adjustment on noise-free observations, the occluder segments, the comparison without ids and
// the anchor file.

#include "drive_anchors.hpp"
#include "drive_bundle_adjustment.hpp"
#include "drive_landmark_track.hpp"
#include "drive_map_comparison.hpp"
#include "drive_occluders.hpp"
#include "survey_map_warnings.hpp"

#include "common/json_config.hpp"

#include <gtest/gtest.h>
#include <unistd.h>
#include <Eigen/LU>

#include <cmath>
#include <fstream>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(LandmarkTrack, ScatterWithTheRangeOffsetTakenOffIsTheCorrectedSightings) {
  // A centre at (5, 5) seen from all around with every range 30 mm long.
  LandmarkTrack track;
  const Eigen::Vector2d centre(5.0, 5.0);
  for (int i = 0; i < 36; ++i) {
    const double from = i * 10.0 * M_PI / 180.0;  // direction from the centre to the laser
    const Eigen::Vector2d beam(-std::cos(from), -std::sin(from));
    track.add({i, 0, centre + 0.03 * beam, beam});
  }
  EXPECT_NEAR(track.scatter(0.0), 0.03, 1e-9);
  EXPECT_NEAR(track.scatter(0.03), 0.0, 1e-6);
  EXPECT_NEAR((track.mean(0.03) - centre).norm(), 0.0, 1e-12);
  EXPECT_GT(track.view_span(), 340.0 * M_PI / 180.0);
  PromotionRule rule;
  EXPECT_EQ(track.promotion_failure(rule, 0.03), "");  // 36 sightings, every view, no scatter
  EXPECT_NE(track.promotion_failure(rule, 0.0).find("scatters 30.0 mm"), std::string::npos);
}

TEST(LandmarkTrack, AGlintSeenFromOneDirectionIsNotPromoted) {
  LandmarkTrack track;
  for (int i = 0; i < 40; ++i) {
    const double from = (i % 5) * 1.0 * M_PI / 180.0;
    track.add({i, 0, Eigen::Vector2d(2.0, 0.0), Eigen::Vector2d(-std::cos(from), -std::sin(from))});
  }
  EXPECT_NE(track.promotion_failure(PromotionRule{}).find("seen over 4.0 deg"), std::string::npos);
}

BundleProblem synthetic_problem(double range_bias) {
  BundleProblem p;
  p.robot_T_laser = {0.3, 0.0, 0.0};
  p.map_p_landmark = {{0, 4}, {4, 4}, {8, 4}, {0, -1}, {4, -1.5}, {8, -1}};
  std::vector<Eigen::Vector2d> truth = p.map_p_landmark;
  for (int k = 0; k < 40; ++k) {
    const Pose2 pose{0.2 * k, 1.0 + 0.3 * std::sin(0.2 * k), 0.05 * k};
    p.odom_T_robot.push_back(pose);  // odometry exact: the landmarks carry the test
    p.map_T_robot.push_back({pose.x + 0.02, pose.y - 0.02, pose.theta + 0.01});
    const Pose2 laser_T_map = (pose * p.robot_T_laser).inverse();
    for (size_t j = 0; j < truth.size(); ++j) {
      const Eigen::Vector2d laser_p = laser_T_map * truth[j];
      p.observations.push_back({k, static_cast<int>(j), 0, laser_p + range_bias * laser_p.normalized(),
                                Eigen::Matrix2d::Identity() * 1e-4});
    }
  }
  p.map_T_robot.front() = p.odom_T_robot.front();  // the held first pose is the true one
  for (auto& m : p.map_p_landmark) m += Eigen::Vector2d(0.05, -0.04);
  return p;
}

TEST(BundleAdjustment, RecoversLandmarksAndRangeOffsetFromNoiseFreeObservations) {
  const BundleProblem p = synthetic_problem(0.025);
  const BundleResult r = adjust_bundle(p, BundleOptions{});
  ASSERT_TRUE(r.ok) << r.message;
  const std::vector<Eigen::Vector2d> truth = synthetic_problem(0.0).map_p_landmark;
  for (size_t j = 0; j < truth.size(); ++j) {
    EXPECT_LT((r.landmarks[j].map_p - (truth[j] - Eigen::Vector2d(0.05, -0.04))).norm(), 1e-6) << j;
    EXPECT_GT(r.landmarks[j].covariance.determinant(), 0.0);
    EXPECT_EQ(r.landmarks[j].observations, 40);
  }
  EXPECT_NEAR(r.range_bias, 0.025, 1e-7);
  EXPECT_GT(r.range_bias_sigma, 0.0);
}

TEST(BundleAdjustment, FrameFreeCovariancesLeaveOutTheHeldPosesUncertainty) {
  // The first pose held: the landmarks far from it carry its heading's uncertainty, which a
  // rigid alignment (and localization in the map) removes; the frame-free covariance does not
  // have it. With anchors the anchors are the frame: no frame-free covariance is computed.
  const BundleProblem p = synthetic_problem(0.0);
  const BundleResult r = adjust_bundle(p, BundleOptions{});
  ASSERT_TRUE(r.ok) << r.message;
  for (const BundleLandmark& l : r.landmarks) {
    EXPECT_GT(l.frame_free_covariance.determinant(), 0.0);
    EXPECT_LT(l.frame_free_covariance.trace(), l.covariance.trace());
  }
  // Landmark 2 at (8, 4) is the farthest from the held pose at (0, 1): its frame share is the largest.
  EXPECT_GT(r.landmarks[2].covariance.trace() / r.landmarks[2].frame_free_covariance.trace(),
            r.landmarks[0].covariance.trace() / r.landmarks[0].frame_free_covariance.trace());
  BundleProblem anchored = p;
  const std::vector<Eigen::Vector2d> truth = synthetic_problem(0.0).map_p_landmark;
  anchored.anchors = {{0, truth[0]}, {2, truth[2]}};
  const BundleResult a = adjust_bundle(anchored, BundleOptions{});
  ASSERT_TRUE(a.ok) << a.message;
  EXPECT_EQ(a.landmarks[4].frame_free_covariance, Eigen::Matrix2d::Zero());
  EXPECT_GT(a.landmarks[4].covariance.determinant(), 0.0);
}

TEST(BundleAdjustment, AnchorsHoldTheirLandmarksAndFreeTheFirstPose) {
  BundleProblem p = synthetic_problem(0.0);
  const std::vector<Eigen::Vector2d> truth = synthetic_problem(0.0).map_p_landmark;
  p.anchors = {{0, truth[0] - Eigen::Vector2d(0.05, -0.04)}, {2, truth[2] - Eigen::Vector2d(0.05, -0.04)}};
  const BundleResult r = adjust_bundle(p, BundleOptions{});
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.landmarks[0].covariance, Eigen::Matrix2d::Zero());  // held: no covariance
  EXPECT_LT((r.landmarks[4].map_p - (truth[4] - Eigen::Vector2d(0.05, -0.04))).norm(), 1e-6);
}

TEST(BundleAdjustment, ARobotStandingStillWeighsAsOneViewNotAsEveryScan) {
  // The synthetic drive, then 200 scans standing at its last pose whose detections of landmark
  // 0 all sit 20 mm across the beam: a 2-beam fit between the same two beams repeats its error
  // scan after scan. As 200 independent detections they would outweigh the 40 good views.
  BundleProblem p = synthetic_problem(0.0);
  p.angle_increment = 0.5 * M_PI / 180.0;
  const std::vector<Eigen::Vector2d> truth = synthetic_problem(0.0).map_p_landmark;
  const Pose2 standing = p.odom_T_robot.back();
  const Pose2 laser_T_map = (standing * p.robot_T_laser).inverse();
  for (int k = 0; k < 200; ++k) {
    const int pose = static_cast<int>(p.map_T_robot.size());
    p.odom_T_robot.push_back(standing);
    p.map_T_robot.push_back(p.map_T_robot.back());
    for (size_t j = 0; j < truth.size(); ++j) {
      const Eigen::Vector2d laser_p = laser_T_map * (truth[j] - Eigen::Vector2d(0.05, -0.04));
      const Eigen::Vector2d across(-laser_p.normalized().y(), laser_p.normalized().x());
      p.observations.push_back({pose, static_cast<int>(j), 0, laser_p + (j == 0 ? 0.02 : 0.0) * across,
                                Eigen::Matrix2d::Identity() * 1e-4});
    }
  }
  const auto error_of_landmark_0 = [&](double same_view_beam_steps) {
    BundleOptions o;
    o.estimate_range_bias = false;
    o.same_view_beam_steps = same_view_beam_steps;
    const BundleResult r = adjust_bundle(p, o);
    EXPECT_TRUE(r.ok) << r.message;
    return (r.landmarks[0].map_p - (truth[0] - Eigen::Vector2d(0.05, -0.04))).norm();
  };
  EXPECT_LT(error_of_landmark_0(0.5), 0.0015);  // 0.3 mm: the standstill weighs as one of 41 views
  EXPECT_GT(error_of_landmark_0(0.0), 0.008);   // 10.6 mm: every scan counted, pulled half the way
}

TEST(Occluders, TwoWallsOfCellsBecomeTwoSegmentsWithTheirEnds) {
  std::vector<Eigen::Vector2d> cells;
  for (int i = 0; i < 100; ++i) cells.emplace_back(0.025 + 0.05 * i, 0.025);     // 5 m along x
  for (int i = 0; i < 40; ++i) cells.emplace_back(6.025, 1.025 + 0.05 * i);      // 2 m along y
  for (int i = 0; i < 3; ++i) cells.emplace_back(3.0 + 0.4 * i, 3.0 + 0.7 * i);  // scattered noise
  const std::vector<MapOccluder> walls = segments_from_cells(cells, OccluderConfig{});
  ASSERT_EQ(walls.size(), 2u);
  EXPECT_EQ(walls[0].name, "wall 1");
  const double x0 = std::min(walls[0].map_points[0].x(), walls[0].map_points[1].x());
  const double x1 = std::max(walls[0].map_points[0].x(), walls[0].map_points[1].x());
  EXPECT_NEAR(x0, 0.0, 1e-6);  // the cells' outer edges
  EXPECT_NEAR(x1, 5.0, 1e-6);
  EXPECT_NEAR(walls[0].map_points[0].y(), 0.025, 1e-6);
  EXPECT_NEAR(walls[1].map_points[0].x(), 6.025, 1e-6);
  EXPECT_NEAR((walls[1].map_points[1] - walls[1].map_points[0]).norm(), 2.0, 0.01);
}

MapReflector reflector(int id, const Eigen::Vector2d& map_p) {
  MapReflector r;
  r.id = id;
  r.map_p_center = map_p;
  return r;
}

TEST(MapComparison, FindsTheAlignmentWithoutIdsAndNamesExtraAndMissingEntries) {
  ReflectorMap truth;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> where(0.0, 20.0);
  for (int id = 1; id <= 12; ++id) truth.reflectors.push_back(reflector(id, {where(rng), where(rng)}));
  const Pose2 map_T_truth{3.0, -2.0, 0.7};
  ReflectorMap map;
  for (size_t i = 1; i < truth.reflectors.size(); ++i) {  // truth id 1 missing, ids renumbered
    MapReflector r = reflector(static_cast<int>(100 + i), map_T_truth * truth.reflectors[i].map_p_center);
    r.map_p_center.x() += (i == 5 ? 0.004 : 0.0);
    r.map_cov_center = Eigen::Matrix2d::Identity() * 1e-6;
    map.reflectors.push_back(r);
  }
  map.reflectors.push_back(reflector(999, map_T_truth * Eigen::Vector2d(50.0, 50.0)));  // a distractor
  const MapComparison c = compare_maps(map, truth);
  ASSERT_TRUE(c.aligned);
  EXPECT_EQ(c.matched.size(), 11u);
  EXPECT_EQ(c.extra_map_ids, std::vector<int>{999});
  EXPECT_EQ(c.missing_truth_ids, std::vector<int>{1});
  EXPECT_NEAR(c.truth_T_map.theta, -0.7, 1e-3);
  EXPECT_EQ(c.worst_map_id, 105);
  EXPECT_NEAR(c.worst, 0.004, 0.0007);
  EXPECT_EQ(c.with_covariance, 11);
  EXPECT_EQ(c.within_3_sigma, 10);  // 4 mm at 1 mm sigma is outside
}

TEST(MapComparison, MeasuresTheScaleOfAMapThatIsTooLarge) {
  ReflectorMap truth, map;
  for (int id = 1; id <= 8; ++id) {
    const Eigen::Vector2d p(2.5 * id, id % 2 == 0 ? 0.0 : 12.0);
    truth.reflectors.push_back(reflector(id, p));
    map.reflectors.push_back(
        reflector(id, Eigen::Vector2d(10.0, 6.0) + 1.001 * (p - Eigen::Vector2d(10.0, 6.0))));
  }
  const MapComparison c = compare_maps(map, truth);
  ASSERT_EQ(c.matched.size(), 8u);
  EXPECT_NEAR(c.scale_ppm, 1000.0, 1.0);
  EXPECT_LT(c.rms_after_scale, 1e-9);
  EXPECT_GT(c.rms, 0.003);  // a rigid alignment leaves the scale as error
}

std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "refloc_survey_" + std::to_string(getpid()) + "_" + name;
  std::ofstream(path) << text;
  return path;
}

TEST(SurveyAnchors, ReadsIdsCoordinatesAndNearPoints) {
  const std::string path = write_temp("anchors.json", R"({"anchors": [{"id": 1, "x_m": 1.5, "y_m": 0.1},
      {"id": 5, "x_m": 17.8, "y_m": 0.1, "near_x_m": 14.9, "near_y_m": -2.8}]})");
  const std::vector<SurveyAnchor> a = load_survey_anchors(path);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[1].id, 5);
  EXPECT_EQ(a[0].near, Eigen::Vector2d(1.5, 0.1));
  EXPECT_EQ(a[1].near, Eigen::Vector2d(14.9, -2.8));
}

TEST(SurveyAnchors, RefusesOneAnchorATwiceUsedIdAndUnknownKeysNamingTheKey) {
  const auto message = [](const std::string& text) {
    try {
      load_survey_anchors(write_temp("bad.json", text));
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(R"({"anchors": [{"id": 1, "x_m": 0, "y_m": 0}]})").find("/anchors: 2 or more"),
            std::string::npos);
  EXPECT_NE(message(R"({"anchors": [{"id": 1, "x_m": 0, "y_m": 0}, {"id": 1, "x_m": 1, "y_m": 0}]})")
                .find("/anchors/1/id: id 1 is given twice"),
            std::string::npos);
  EXPECT_NE(message(R"({"anchors": [{"id": 1, "x_m": 0, "y_m": 0}, {"id": 2, "x": 1, "y_m": 0}]})")
                .find("/anchors/1/x_m"),
            std::string::npos);
}

TEST(SurveyMapWarnings, ASymmetricLayoutIsWrittenWithAWarningTheDemoHallWithout) {
  const std::string dir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";
  const std::string symmetric = self_similar_map_warning(load_reflector_map(dir + "map_symmetric.json"));
  EXPECT_NE(symmetric.find("12 of its 12 reflectors"), std::string::npos) << symmetric;
  EXPECT_EQ(self_similar_map_warning(load_reflector_map(dir + "map_demo_v2.json")), "");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
