#include "mecanum_odometry/exact_arc.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace {

TEST(ExactArc, ConstantTwistEndsOnTheAnalyticCircle) {
  // vx = 0.5 m/s, wz = 0.5 rad/s: circle of radius 1 m centred at (0, 1).
  for (double t : {0.1, 1.0, M_PI, 5.0}) {
    const Pose2 p = exp_twist({0.5, 0.0, 0.5}, t);
    EXPECT_NEAR(p.x, std::sin(0.5 * t), 1e-12);
    EXPECT_NEAR(p.y, 1.0 - std::cos(0.5 * t), 1e-12);
    EXPECT_NEAR(p.theta, wrap_angle(0.5 * t), 1e-12);
  }
}

TEST(ExactArc, SmallRotationLimitIsStraightLine) {
  const Pose2 p = exp_twist({1.0, -0.5, 1e-9}, 2.0);
  EXPECT_NEAR(p.x, 2.0, 1e-8);
  EXPECT_NEAR(p.y, -1.0, 1e-8);
}

TEST(ExactArc, SplittingTheIntervalGivesTheSameArc) {
  const BodyTwist twist{0.3, 0.2, -0.8};
  Pose2 steps;
  for (int i = 0; i < 100; ++i) steps = steps * exp_twist(twist, 0.01);
  const Pose2 once = exp_twist(twist, 1.0);
  EXPECT_TRUE(approx_equal(steps, once, 1e-12, 1e-12));
}

TEST(ExactArc, LogInvertsExpOverRandomTwists) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> v(-1.0, 1.0), w(-3.0, 3.0);
  for (int i = 0; i < 1000; ++i) {
    const BodyTwist twist{v(rng), v(rng), w(rng)};
    const BodyTwist back = log_pose(exp_twist(twist, 1.0));
    ASSERT_NEAR(back.vx, twist.vx, 1e-9);
    ASSERT_NEAR(back.vy, twist.vy, 1e-9);
    ASSERT_NEAR(back.wz, twist.wz, 1e-12);
  }
}

}  // namespace
}  // namespace refloc
