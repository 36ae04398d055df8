#include "pose_solver/paper_trilateration.hpp"
#include "pose_solver/pose_solver.hpp"

#include "solver_scenario.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<PointObservation> exact_observations(const ReflectorMap& map, const Pose2& map_T_laser) {
  std::vector<PointObservation> obs;
  for (const auto& r : map.reflectors) {
    PointObservation o;
    o.map_p = r.map_p_center;
    o.laser_p = map_T_laser.inverse() * r.map_p_center;
    o.range = o.laser_p.norm();
    o.bearing = std::atan2(o.laser_p.y(), o.laser_p.x());
    obs.push_back(o);
  }
  return obs;
}

TEST(PaperTrilateration, Eq4RecoversTheLaserPositionFromExactRanges) {
  const Pose2 map_T_laser{5.0, 4.0, 0.8};
  const auto obs = exact_observations(testing::hall_map(), map_T_laser);
  Eigen::Vector2d p;
  ASSERT_TRUE(trilaterate_position(obs, nullptr, 1e-6, p));
  EXPECT_NEAR(p.x(), 5.0, 1e-9);
  EXPECT_NEAR(p.y(), 4.0, 1e-9);
}

TEST(PaperTrilateration, Eq4NeedsThreeNonCollinearReflectors) {
  const ReflectorMap line = testing::map_from_points({{0, 0}, {5, 0}, {10, 0}, {15, 0}});
  const auto obs = exact_observations(line, Pose2{5, 3, 0});
  Eigen::Vector2d p;
  EXPECT_FALSE(trilaterate_position(obs, nullptr, 1e-6, p));
  const auto two = std::vector<PointObservation>(obs.begin(), obs.begin() + 2);
  EXPECT_FALSE(trilaterate_position(two, nullptr, 1e-6, p));
}

TEST(PaperTrilateration, Eq6And7GiveTheHeadingAsTheMeanOfTheAlphas) {
  const Pose2 map_T_laser{5.0, 4.0, 0.8};
  const auto obs = exact_observations(testing::hall_map(), map_T_laser);
  EXPECT_NEAR(paper_mean_heading(obs, {5.0, 4.0}), 0.8, 1e-12);
  EXPECT_NEAR(circular_mean_heading(obs, nullptr, {5.0, 4.0}), 0.8, 1e-12);
}

TEST(PaperTrilateration, Eq7ArithmeticMeanFailsNearPiWhereTheCircularMeanDoesNot) {
  // The alphas straddle +-pi: wrapped terms near +pi and -pi average to about 0.
  std::vector<PointObservation> obs(2);
  obs[0].map_p = {1, 0};
  obs[0].bearing = -(M_PI - 0.01);  // alpha_0 = 0 - bearing = pi - 0.01
  obs[1].map_p = {1, 0};
  obs[1].bearing = M_PI - 0.01;  // alpha_1 = -(pi - 0.01)
  EXPECT_NEAR(paper_mean_heading(obs, {0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(circular_mean_heading(obs, nullptr, {0, 0})), M_PI, 1e-12);
}

TEST(PaperTrilateration, Eq8MovesFromTheLaserToTheRobotCentre) {
  // Laser 0.4 m behind and 0.3 m left of the centre (the paper's rear corner):
  // OO' = 0.5 m, and with the robot heading 90 deg the centre is 0.4 m north and 0.3 m east of the laser.
  const Eigen::Vector2d p = paper_robot_position({10.0, 20.0}, M_PI / 2, testing::corner_mount());
  EXPECT_NEAR(p.x(), 10.3, 1e-12);
  EXPECT_NEAR(p.y(), 20.4, 1e-12);
  // Same as composing map_T_laser with laser_T_robot.
  const Pose2 map_T_laser{10.0, 20.0, M_PI / 2};
  const Pose2 map_T_robot = map_T_laser * testing::corner_mount().inverse();
  EXPECT_NEAR(p.x(), map_T_robot.x, 1e-12);
  EXPECT_NEAR(p.y(), map_T_robot.y, 1e-12);
}

TEST(PaperSolver, ReproducesTheRobotPoseFromExactDetections) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{6.0, 5.0, 2.0};
  testing::SyntheticSensor sensor;
  sensor.range_sigma = sensor.bearing_sigma = 0.0;
  sensor.field_of_view = 2 * M_PI;
  std::mt19937 rng(30);
  const auto scan = testing::render_detections(map, truth * testing::corner_mount(), sensor, rng);
  ASSERT_EQ(scan.detections.size(), 8u);
  SolverConfig config;
  config.mode = SolverMode::kPaper;
  PoseSolver solver(config, testing::corner_mount());
  PoseSolution solution;
  solver.solve(scan.detections, testing::true_matches(scan, map), solution);
  EXPECT_EQ(solution.status, SolveStatus::kOk);
  EXPECT_EQ(solution.reflectors_used, 8);
  EXPECT_TRUE(approx_equal(solution.map_T_robot, truth, 1e-9, 1e-9));
  EXPECT_LT(solution.rms_residual, 1e-9);
}

TEST(PaperSolver, HeadingNearPiIsWrongAsPublished) {
  // Documents the baseline's weakness the default mode fixes.
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{8.0, 6.0, M_PI - 0.0005};  // noise puts some alpha_i across +-pi
  testing::SyntheticSensor sensor;
  sensor.field_of_view = 2 * M_PI;
  std::mt19937 rng(31);
  const auto scan = testing::render_detections(map, truth, sensor, rng);
  SolverConfig paper_config;
  paper_config.mode = SolverMode::kPaper;
  PoseSolution paper, fixed;
  PoseSolver(paper_config, Pose2{}).solve(scan.detections, testing::true_matches(scan, map), paper);
  PoseSolver(SolverConfig{}, Pose2{}).solve(scan.detections, testing::true_matches(scan, map), fixed);
  EXPECT_GT(std::abs(angle_diff(paper.map_T_robot.theta, truth.theta)), 0.5);
  EXPECT_LT(std::abs(angle_diff(fixed.map_T_robot.theta, truth.theta)), 0.01);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
