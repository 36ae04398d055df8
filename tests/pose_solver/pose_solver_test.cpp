#include "pose_solver/pose_solver.hpp"

#include "solver_scenario.hpp"

#include <gtest/gtest.h>
#include <Eigen/LU>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(PoseSolver, RecoversThePoseWithinNoise) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(40);
  std::uniform_real_distribution<double> ux(3, 13), uy(3, 9), ua(-M_PI, M_PI);
  PoseSolver solver(SolverConfig{}, testing::corner_mount());
  PoseSolution solution;
  for (int trial = 0; trial < 500; ++trial) {
    const Pose2 truth{ux(rng), uy(rng), ua(rng)};
    const auto scan =
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
    ASSERT_GE(scan.detections.size(), 4u);
    solver.solve(scan.detections, testing::true_matches(scan, map), solution);
    ASSERT_EQ(solution.status, SolveStatus::kOk);
    ASSERT_EQ(solution.reflectors_used, static_cast<int>(scan.detections.size()));
    // 4 sigma of the reported covariance, and an absolute sanity bound.
    EXPECT_LT(std::hypot(solution.map_T_robot.x - truth.x, solution.map_T_robot.y - truth.y), 0.03);
    EXPECT_LT(std::abs(angle_diff(solution.map_T_robot.theta, truth.theta)), 0.005);
    EXPECT_LT(solution.rms_residual, 0.03);
  }
}

TEST(PoseSolver, CovarianceIsConsistentNeesOverManyDraws) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{7.0, 5.0, 0.4};
  std::mt19937 rng(41);
  PoseSolver solver(SolverConfig{}, testing::corner_mount());
  PoseSolution solution;
  double nees_sum = 0.0;
  const int draws = 3000;
  for (int i = 0; i < draws; ++i) {
    const auto scan =
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
    solver.solve(scan.detections, testing::true_matches(scan, map), solution);
    ASSERT_NE(solution.status, SolveStatus::kLost);
    const Eigen::Vector3d e(solution.map_T_robot.x - truth.x, solution.map_T_robot.y - truth.y,
                            angle_diff(solution.map_T_robot.theta, truth.theta));
    nees_sum += e.dot(solution.covariance.inverse() * e);
  }
  const double nees = nees_sum / draws;
  std::printf("mean NEES %.3f (3 expected) over %d draws\n", nees, draws);
  EXPECT_NEAR(nees, 3.0, 0.3);
}

TEST(PoseSolver, DefaultModeIsMoreAccurateInPositionAndNoWorseInHeadingThanPaper) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(46);
  std::uniform_real_distribution<double> ux(3, 13), uy(3, 9), ua(-M_PI, M_PI);
  SolverConfig paper_config;
  paper_config.mode = SolverMode::kPaper;
  PoseSolver paper(paper_config, testing::corner_mount()), joint(SolverConfig{}, testing::corner_mount());
  PoseSolution a, b;
  double paper_xy2 = 0, joint_xy2 = 0, paper_th2 = 0, joint_th2 = 0;
  const int draws = 2000;
  for (int i = 0; i < draws; ++i) {
    // Headings away from +-pi, where eq. 7 would fail outright.
    const Pose2 truth{ux(rng), uy(rng), 0.8 * ua(rng)};
    const auto scan =
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
    const auto matches = testing::true_matches(scan, map);
    paper.solve(scan.detections, matches, a);
    joint.solve(scan.detections, matches, b);
    paper_xy2 += std::pow(a.map_T_robot.x - truth.x, 2) + std::pow(a.map_T_robot.y - truth.y, 2);
    joint_xy2 += std::pow(b.map_T_robot.x - truth.x, 2) + std::pow(b.map_T_robot.y - truth.y, 2);
    paper_th2 += std::pow(angle_diff(a.map_T_robot.theta, truth.theta), 2);
    joint_th2 += std::pow(angle_diff(b.map_T_robot.theta, truth.theta), 2);
  }
  const double paper_xy = std::sqrt(paper_xy2 / draws), joint_xy = std::sqrt(joint_xy2 / draws);
  const double paper_th = std::sqrt(paper_th2 / draws), joint_th = std::sqrt(joint_th2 / draws);
  std::printf(
      "RMS position error: paper %.2f mm, default %.2f mm; heading: paper %.3f mrad, default %.3f mrad\n",
      1e3 * paper_xy, 1e3 * joint_xy, 1e3 * paper_th, 1e3 * joint_th);
  EXPECT_LT(joint_xy, paper_xy);
  EXPECT_LT(joint_th, 1.02 * paper_th);  // heading: about equal (both use every bearing)
}

TEST(PoseSolver, RejectsAnOutlierMatch) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{7.0, 5.0, -1.0};
  std::mt19937 rng(42);
  const auto scan =
      testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
  ASSERT_GE(scan.detections.size(), 5u);
  auto matches = testing::true_matches(scan, map);
  // A wrong association: detection 2 claims the reflector of detection 4.
  matches[2].map_id = matches[4].map_id;
  matches[2].map_p_center = matches[4].map_p_center;
  PoseSolver solver(SolverConfig{}, testing::corner_mount());
  PoseSolution solution;
  solver.solve(scan.detections, matches, solution);
  EXPECT_EQ(solution.status, SolveStatus::kOk);
  EXPECT_EQ(solution.reflectors_used, static_cast<int>(matches.size()) - 1);
  EXPECT_EQ(solution.used[2], 0);
  EXPECT_TRUE(approx_equal(solution.map_T_robot, truth, 0.03, 0.005));
}

TEST(PoseSolver, ThreeReflectorsAreDegradedAndTwoAreLost) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{7.0, 5.0, 0.0};
  std::mt19937 rng(43);
  auto scan =
      testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
  auto matches = testing::true_matches(scan, map);
  PoseSolver solver(SolverConfig{}, testing::corner_mount());
  PoseSolution solution;
  matches.resize(3);
  solver.solve(scan.detections, matches, solution);
  EXPECT_EQ(solution.status, SolveStatus::kDegraded);
  EXPECT_EQ(solution.reflectors_used, 3);
  EXPECT_TRUE(approx_equal(solution.map_T_robot, truth, 0.05, 0.01));
  matches.resize(2);
  solver.solve(scan.detections, matches, solution);
  EXPECT_EQ(solution.status, SolveStatus::kLost);
}

TEST(PoseSolver, LargeResidualIsDegraded) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{7.0, 5.0, 0.0};
  std::mt19937 rng(44);
  testing::SyntheticSensor noisy;
  noisy.range_sigma = 0.08;  // far more than the detections' covariance claims
  auto scan = testing::render_detections(map, truth, noisy, rng);
  for (auto& d : scan.detections) d.covariance = Eigen::Matrix2d::Identity() * 0.05 * 0.05;
  PoseSolver solver(SolverConfig{}, Pose2{});
  PoseSolution solution;
  solver.solve(scan.detections, testing::true_matches(scan, map), solution);
  EXPECT_EQ(solution.status, SolveStatus::kDegraded);
  EXPECT_GT(solution.rms_residual, 0.03);
}

TEST(PoseSolver, BadDetectionIndexIsSkipped) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(45);
  const auto scan = testing::render_detections(map, Pose2{7, 5, 0}, testing::SyntheticSensor{}, rng);
  auto matches = testing::true_matches(scan, map);
  matches.push_back({99, 1, {0, 0}, 0.06});
  PoseSolver solver(SolverConfig{}, Pose2{});
  PoseSolution solution;
  solver.solve(scan.detections, matches, solution);
  EXPECT_EQ(solution.status, SolveStatus::kOk);
  EXPECT_EQ(solution.used.back(), 0);
  EXPECT_EQ(solution.reflectors_used, static_cast<int>(scan.detections.size()));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
