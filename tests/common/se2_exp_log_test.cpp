// The SE(2) exponential and logarithm (common/se2.hpp): exact arcs, one angle
// convention, and exp/log inverse over many random elements.

#include "common/se2.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(Se2Exp, ConstantTwistEndsOnTheAnalyticCircle) {
  // vx = 0.5 m/s, wz = 0.5 rad/s: circle of radius 1 m centred at (0, 1).
  for (double t : {0.1, 1.0, M_PI, 5.0}) {
    const Pose2 p = se2_exp({0.5, 0.0, 0.5}, t);
    EXPECT_NEAR(p.x, std::sin(0.5 * t), 1e-12);
    EXPECT_NEAR(p.y, 1.0 - std::cos(0.5 * t), 1e-12);
    EXPECT_NEAR(p.theta, wrap_angle(0.5 * t), 1e-12);
  }
}

TEST(Se2Exp, QuarterCircleOfRadiusTwo) {
  // v = 1 m/s, w = 0.5 rad/s for pi seconds.
  const Pose2 end = se2_exp(BodyTwist{1.0, 0.0, 0.5}, M_PI);
  EXPECT_NEAR(end.x, 2.0, 1e-12);
  EXPECT_NEAR(end.y, 2.0, 1e-12);
  EXPECT_NEAR(end.theta, M_PI / 2, 1e-12);
}

TEST(Se2Exp, SmallRotationLimitIsStraightLine) {
  const Pose2 p = se2_exp({1.0, -0.5, 1e-9}, 2.0);
  EXPECT_NEAR(p.x, 2.0, 1e-8);
  EXPECT_NEAR(p.y, -1.0, 1e-8);
  const Pose2 tiny = se2_exp(BodyTwist{1.0, 0.0, 1e-9}, 1.0);
  EXPECT_NEAR(tiny.x, 1.0, 1e-12);
  EXPECT_NEAR(tiny.y, 0.5e-9, 1e-15);
}

TEST(Se2Exp, SplittingTheIntervalGivesTheSameArc) {
  const BodyTwist twist{0.3, 0.2, -0.8};
  Pose2 steps;
  for (int i = 0; i < 100; ++i) steps = steps * se2_exp(twist, 0.01);
  const Pose2 once = se2_exp(twist, 1.0);
  EXPECT_TRUE(approx_equal(steps, once, 1e-12, 1e-12));
}

TEST(Se2Exp, HeadingIsWrappedLikeEveryPose) {
  // Three quarters of a turn ends at heading -pi/2, not 3 pi / 2.
  const Pose2 p = se2_exp({0.0, 0.0, 1.5 * M_PI}, 1.0);
  EXPECT_NEAR(p.theta, -M_PI / 2, 1e-12);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> v(-2.0, 2.0), w(-20.0, 20.0);
  for (int i = 0; i < 10000; ++i) {
    const Pose2 q = se2_exp({v(rng), v(rng), w(rng)}, 1.0);
    ASSERT_GT(q.theta, -M_PI);
    ASSERT_LE(q.theta, M_PI);
  }
}

TEST(Se2Log, LogInvertsExpOverRandomTwists) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> v(-1.0, 1.0), w(-3.0, 3.0);
  for (int i = 0; i < 10000; ++i) {
    const BodyTwist twist{v(rng), v(rng), w(rng)};
    const BodyTwist back = se2_log(se2_exp(twist, 1.0));
    ASSERT_NEAR(back.vx, twist.vx, 1e-9);
    ASSERT_NEAR(back.vy, twist.vy, 1e-9);
    ASSERT_NEAR(back.wz, twist.wz, 1e-12);
  }
}

TEST(Se2Log, ExpInvertsLogOverRandomPoses) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> xy(-20.0, 20.0), th(-M_PI, M_PI);
  for (int i = 0; i < 10000; ++i) {
    const Pose2 pose{xy(rng), xy(rng), th(rng)};
    const Pose2 back = se2_exp(se2_log(pose));
    ASSERT_TRUE(approx_equal(back, pose, 1e-9, 1e-12)) << pose.x << " " << pose.y << " " << pose.theta;
  }
}

TEST(Se2Log, UnwrappedHeadingIsReadWrapped) {
  // The same rigid transform written with theta + 2 pi has the same logarithm.
  const Pose2 wrapped{1.0, -2.0, 0.7};
  const Pose2 unwrapped{1.0, -2.0, 0.7 + 2.0 * M_PI};
  const BodyTwist a = se2_log(wrapped), b = se2_log(unwrapped);
  EXPECT_NEAR(a.vx, b.vx, 1e-12);
  EXPECT_NEAR(a.vy, b.vy, 1e-12);
  EXPECT_NEAR(a.wz, b.wz, 1e-12);
  EXPECT_NEAR(b.wz, 0.7, 1e-12);
}

TEST(Se2Log, InterpolatingAlongTheArcSplitsTheStep) {
  // exp(alpha * log(x)) composed with exp((1 - alpha) * log(x)) is x (one arc).
  const Pose2 x{0.4, 0.1, 0.6};
  const BodyTwist t = se2_log(x);
  const Pose2 split = se2_exp(t, 0.3) * se2_exp(t, 0.7);
  EXPECT_TRUE(approx_equal(split, x, 1e-12, 1e-12));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
