#include "common/mecanum_kinematics.hpp"

#include <gtest/gtest.h>

#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

const MecanumKinematics kKinematics(0.076, 0.25, 0.22);

TEST(MecanumKinematics, ForwardOfInverseIsIdentityOverRandomTwists) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> v(-2.0, 2.0), w(-3.0, 3.0);
  for (int i = 0; i < 10000; ++i) {
    const BodyTwist twist{v(rng), v(rng), w(rng)};
    const BodyTwist back = kKinematics.forward(kKinematics.inverse(twist));
    ASSERT_NEAR(back.vx, twist.vx, 1e-12);
    ASSERT_NEAR(back.vy, twist.vy, 1e-12);
    ASSERT_NEAR(back.wz, twist.wz, 1e-12);
    ASSERT_NEAR(kKinematics.redundancy_residual(kKinematics.inverse(twist)), 0.0, 1e-12);
  }
}

TEST(MecanumKinematics, ForwardMotionSpinsAllWheelsForwardEqually) {
  const WheelArray w = kKinematics.inverse({0.76, 0.0, 0.0});
  for (double wi : w) EXPECT_NEAR(wi, 10.0, 1e-12);
}

TEST(MecanumKinematics, LeftStrafeSpinsFrontLeftAndRearRightBackwards) {
  const WheelArray w = kKinematics.inverse({0.0, 0.76, 0.0});
  EXPECT_NEAR(w[0], -10.0, 1e-12);  // front-left
  EXPECT_NEAR(w[1], 10.0, 1e-12);   // front-right
  EXPECT_NEAR(w[2], -10.0, 1e-12);  // rear-right
  EXPECT_NEAR(w[3], 10.0, 1e-12);   // rear-left
}

TEST(MecanumKinematics, CounterClockwiseTurnSpinsRightWheelsForward) {
  const WheelArray w = kKinematics.inverse({0.0, 0.0, 1.0});
  const double expected = (0.25 + 0.22) / 0.076;
  EXPECT_NEAR(w[0], -expected, 1e-12);
  EXPECT_NEAR(w[1], expected, 1e-12);
  EXPECT_NEAR(w[2], expected, 1e-12);
  EXPECT_NEAR(w[3], -expected, 1e-12);
}

TEST(MecanumKinematics, OneWheelDisagreeingShowsInTheResidual) {
  WheelArray w = kKinematics.inverse({0.5, 0.0, 0.0});
  w[0] *= 1.2;  // front-left turns 20 % faster than the ground moves
  EXPECT_NEAR(std::abs(kKinematics.redundancy_residual(w)), 0.076 / 4.0 * 0.2 * 0.5 / 0.076, 1e-12);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
