#include "reflector_matcher/rigid_fit_2d.hpp"

#include <gtest/gtest.h>

#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(RigidFit2d, RecoversAnExactTransformFromThreePoints) {
  const Pose2 b_T_a{3.0, -2.0, 2.5};
  RigidFit2d fit;
  for (const Eigen::Vector2d& a : {Eigen::Vector2d(1, 0), Eigen::Vector2d(0, 5), Eigen::Vector2d(-3, 2)}) {
    fit.add(a, b_T_a * a);
  }
  Pose2 solved;
  ASSERT_TRUE(fit.solve(solved));
  EXPECT_TRUE(approx_equal(solved, b_T_a, 1e-12, 1e-12));
}

TEST(RigidFit2d, LeastSquaresWithNoiseIsCloseToTruth) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-10, 10);
  std::normal_distribution<double> noise(0.0, 0.01);
  const Pose2 b_T_a{-4.0, 7.0, -1.0};
  RigidFit2d fit;
  for (int i = 0; i < 50; ++i) {
    const Eigen::Vector2d a(u(rng), u(rng));
    fit.add(a, b_T_a * a + Eigen::Vector2d(noise(rng), noise(rng)));
  }
  Pose2 solved;
  ASSERT_TRUE(fit.solve(solved));
  EXPECT_TRUE(approx_equal(solved, b_T_a, 0.01, 0.002));
}

TEST(RigidFit2d, RefusesFewerThanTwoPointsOrCoincidentPoints) {
  RigidFit2d fit;
  Pose2 solved;
  EXPECT_FALSE(fit.solve(solved));
  fit.add({1, 1}, {2, 2});
  EXPECT_FALSE(fit.solve(solved));
  fit.add({1, 1}, {2, 2});
  EXPECT_FALSE(fit.solve(solved));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
