// Covariance propagation through SE(2) composition (common/covariance_propagation.hpp):
// the Jacobians against finite differences over many random poses, and the mount
// lever arm.

#include "common/covariance_propagation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

Pose2 perturbed(const Pose2& p, int axis, double h) {
  Pose2 q = p;
  if (axis == 0) q.x += h;
  if (axis == 1) q.y += h;
  if (axis == 2) q.theta += h;
  return q;
}

// Central difference of a * b with respect to a (lhs) or to b's body-frame parameters (rhs).
Eigen::Matrix3d numeric_jacobian(const Pose2& a, const Pose2& b, bool lhs) {
  constexpr double kH = 1e-6;
  Eigen::Matrix3d j;
  for (int axis = 0; axis < 3; ++axis) {
    const Pose2 plus = lhs ? perturbed(a, axis, kH) * b : a * perturbed(b, axis, kH);
    const Pose2 minus = lhs ? perturbed(a, axis, -kH) * b : a * perturbed(b, axis, -kH);
    j.col(axis) << (plus.x - minus.x) / (2 * kH), (plus.y - minus.y) / (2 * kH),
        angle_diff(plus.theta, minus.theta) / (2 * kH);
  }
  return j;
}

std::vector<Pose2> random_poses(size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> xy(-10.0, 10.0), th(-M_PI, M_PI);
  std::vector<Pose2> poses;
  for (size_t i = 0; i < n; ++i) poses.push_back({xy(rng), xy(rng), th(rng)});
  return poses;
}

TEST(ComposeJacobian, MatchesFiniteDifferencesOverRandomPoses) {
  const auto poses = random_poses(2000, 5);
  for (size_t i = 0; i + 1 < poses.size(); i += 2) {
    const Pose2 &a = poses[i], &b = poses[i + 1];
    ASSERT_LT((compose_jacobian_lhs(a, b) - numeric_jacobian(a, b, true)).cwiseAbs().maxCoeff(), 1e-6);
    ASSERT_LT((compose_jacobian_rhs(a) - numeric_jacobian(a, b, false)).cwiseAbs().maxCoeff(), 1e-6);
  }
}

TEST(ComposeCovariance, IsTheSumOfBothPropagatedTerms) {
  const Pose2 a{1.0, 2.0, 0.7}, b{0.3, -0.1, 0.2};
  const Eigen::Matrix3d p = Eigen::Vector3d(1e-4, 2e-4, 3e-5).asDiagonal();
  const Eigen::Matrix3d q = Eigen::Vector3d(4e-6, 4e-6, 1e-6).asDiagonal();
  const Eigen::Matrix3d f = compose_jacobian_lhs(a, b), g = compose_jacobian_rhs(a);
  const Eigen::Matrix3d expected = f * p * f.transpose() + g * q * g.transpose();
  EXPECT_LT((compose_covariance(a, p, b, q) - expected).norm(), 1e-18);
  // With an exact increment the robot's own covariance only grows by the lever arm.
  EXPECT_LT((compose_covariance(a, p, b, Eigen::Matrix3d::Zero()) - propagate_through_mount(a, p, b)).norm(),
            1e-18);
}

TEST(PropagateThroughMount, HeadingErrorBecomesSidewaysErrorAtTheLaser) {
  // Laser 0.3 m ahead; robot heading sigma 0.01 rad, no position error: at heading 0
  // the laser position is uncertain sideways by 0.3 * 0.01 m, fully correlated with heading.
  const Pose2 map_T_robot{5.0, 5.0, 0.0}, robot_T_laser{0.3, 0.0, 0.0};
  const Eigen::Matrix3d p = Eigen::Vector3d(0.0, 0.0, 1e-4).asDiagonal();
  const Eigen::Matrix3d laser = propagate_through_mount(map_T_robot, p, robot_T_laser);
  EXPECT_NEAR(laser(0, 0), 0.0, 1e-18);
  EXPECT_NEAR(laser(1, 1), 0.3 * 0.3 * 1e-4, 1e-15);
  EXPECT_NEAR(laser(1, 2), 0.3 * 1e-4, 1e-15);
  EXPECT_NEAR(laser(2, 2), 1e-4, 1e-15);
  // A laser on the robot centre sees the robot covariance unchanged.
  const Eigen::Matrix3d full = Eigen::Vector3d(1e-3, 2e-3, 1e-4).asDiagonal();
  EXPECT_LT((propagate_through_mount({1.0, -1.0, 2.0}, full, Pose2{}) - full).norm(), 1e-18);
}

TEST(PropagateThroughMount, AgreesWithSampledPosesToFirstOrder) {
  // 20000 samples of a small robot pose error, pushed through the mount exactly.
  const Pose2 map_T_robot{2.0, -3.0, 1.1}, robot_T_laser{0.3, 0.05, 0.1};
  const Eigen::Vector3d sigma(0.01, 0.02, 0.005);
  const Eigen::Matrix3d p = sigma.cwiseProduct(sigma).asDiagonal();
  const Pose2 mean = map_T_robot * robot_T_laser;
  std::mt19937 rng(9);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Matrix3d sampled = Eigen::Matrix3d::Zero();
  constexpr int kSamples = 20000;
  for (int i = 0; i < kSamples; ++i) {
    const Pose2 robot{map_T_robot.x + sigma(0) * n(rng), map_T_robot.y + sigma(1) * n(rng),
                      map_T_robot.theta + sigma(2) * n(rng)};
    const Pose2 laser = robot * robot_T_laser;
    const Eigen::Vector3d e(laser.x - mean.x, laser.y - mean.y, angle_diff(laser.theta, mean.theta));
    sampled += e * e.transpose() / kSamples;
  }
  const Eigen::Matrix3d predicted = propagate_through_mount(map_T_robot, p, robot_T_laser);
  EXPECT_LT((sampled - predicted).cwiseAbs().maxCoeff(), 0.05 * predicted.cwiseAbs().maxCoeff());
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
