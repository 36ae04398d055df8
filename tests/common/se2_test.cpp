#include "common/se2.hpp"

#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::vector<Pose2> random_poses(size_t n) {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> xy(-50.0, 50.0), th(-10.0, 10.0);
  std::vector<Pose2> poses;
  for (size_t i = 0; i < n; ++i) poses.push_back({xy(rng), xy(rng), th(rng)});
  return poses;
}

TEST(Pose2, ComposeWithInverseIsIdentity) {
  for (const Pose2 &a : random_poses(200)) {
    EXPECT_TRUE(approx_equal(a * a.inverse(), Pose2{}, 1e-9, 1e-12));
    EXPECT_TRUE(approx_equal(a.inverse() * a, Pose2{}, 1e-9, 1e-12));
  }
}

TEST(Pose2, CompositionIsAssociative) {
  const auto poses = random_poses(300);
  for (size_t i = 0; i + 2 < poses.size(); i += 3) {
    const Pose2 &a = poses[i], &b = poses[i + 1], &c = poses[i + 2];
    EXPECT_TRUE(approx_equal((a * b) * c, a * (b * c), 1e-9, 1e-12));
  }
}

TEST(Pose2, ActionMatchesHomogeneousMatrix) {
  const auto poses = random_poses(100);
  for (size_t i = 0; i + 1 < poses.size(); i += 2) {
    const Pose2 &a = poses[i], &b = poses[i + 1];
    const Eigen::Vector2d p(b.x, b.y);
    const Eigen::Vector3d expected = a.matrix() * p.homogeneous();
    EXPECT_NEAR(((a * p) - expected.head<2>()).norm(), 0.0, 1e-9);
    EXPECT_NEAR(((a * b).matrix() - a.matrix() * b.matrix()).norm(), 0.0, 1e-9);
  }
}

TEST(Pose2, PaperEquationOneIsThePoseAction) {
  // Paper eq. 1: x_s = x0 + x' cos a0 - y' sin a0; y_s = y0 + x' sin a0 + y' cos a0.
  const Pose2 map_T_laser{1.0, 2.0, 0.5};
  const Eigen::Vector2d laser_p{3.0, -1.0};
  const Eigen::Vector2d map_p = map_T_laser * laser_p;
  EXPECT_NEAR(map_p.x(), 1.0 + 3.0 * std::cos(0.5) + 1.0 * std::sin(0.5), 1e-12);
  EXPECT_NEAR(map_p.y(), 2.0 + 3.0 * std::sin(0.5) - 1.0 * std::cos(0.5), 1e-12);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
