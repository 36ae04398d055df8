#include "reflector_matcher/triangle_signature.hpp"

#include "common/se2.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

std::array<Eigen::Vector2d, 3> moved(const std::array<Eigen::Vector2d, 3>& p, const Pose2& t) {
  return {t * p[0], t * p[1], t * p[2]};
}

TEST(LargestAngleSignature, RightTriangleHasItsRightAngleAndLegs) {
  const auto s =
      largest_angle_signature({Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0), Eigen::Vector2d(0, 3)});
  EXPECT_NEAR(s.largest_angle, M_PI / 2, 1e-12);
  EXPECT_NEAR(s.long_side, 4.0, 1e-12);
  EXPECT_NEAR(s.short_side, 3.0, 1e-12);
  EXPECT_EQ(s.apex, 0);
  EXPECT_EQ(s.long_end, 1);
  EXPECT_EQ(s.short_end, 2);
}

TEST(LargestAngleSignature, InvariantUnderRigidMotionAndVertexOrder) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-20, 20), ua(-M_PI, M_PI);
  for (int trial = 0; trial < 1000; ++trial) {
    const std::array<Eigen::Vector2d, 3> p = {
        Eigen::Vector2d(u(rng), u(rng)), Eigen::Vector2d(u(rng), u(rng)), Eigen::Vector2d(u(rng), u(rng))};
    const Pose2 t{u(rng), u(rng), ua(rng)};
    const auto a = largest_angle_signature(p);
    const auto q = moved(p, t);
    const auto b = largest_angle_signature({q[2], q[0], q[1]});  // rotated vertex order
    ASSERT_NEAR(a.largest_angle, b.largest_angle, 1e-9);
    ASSERT_NEAR(a.long_side, b.long_side, 1e-9);
    ASSERT_NEAR(a.short_side, b.short_side, 1e-9);
    // Roles follow the vertices: input index k of p is index (k + 1) % 3 of the permuted input.
    ASSERT_EQ((a.apex + 1) % 3, b.apex);
    ASSERT_TRUE(signatures_match(a, b, 1e-6, 1e-6));
  }
}

TEST(LargestAngleSignature, MirrorImageHasTheSameSignature) {
  // The paper's signature cannot tell a triangle from its mirror image.
  const std::array<Eigen::Vector2d, 3> p = {Eigen::Vector2d(0, 0), Eigen::Vector2d(5, 1),
                                            Eigen::Vector2d(2, 3)};
  const std::array<Eigen::Vector2d, 3> m = {Eigen::Vector2d(0, 0), Eigen::Vector2d(5, -1),
                                            Eigen::Vector2d(2, -3)};
  EXPECT_TRUE(signatures_match(largest_angle_signature(p), largest_angle_signature(m), 1e-9, 1e-9));
}

TEST(LargestAngleSignature, ToleranceSeparatesDifferentTriangles) {
  const auto a =
      largest_angle_signature({Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0), Eigen::Vector2d(0, 3)});
  const auto b =
      largest_angle_signature({Eigen::Vector2d(0, 0), Eigen::Vector2d(4.1, 0), Eigen::Vector2d(0, 3)});
  EXPECT_TRUE(signatures_match(a, b, 0.15, 0.01));
  EXPECT_FALSE(signatures_match(a, b, 0.05, 0.01));
}

TEST(SortedSides, AscendingWithOppositeVertices) {
  const auto s = sorted_sides({Eigen::Vector2d(0, 0), Eigen::Vector2d(4, 0), Eigen::Vector2d(0, 3)});
  EXPECT_NEAR(s.side[0], 3.0, 1e-12);
  EXPECT_NEAR(s.side[1], 4.0, 1e-12);
  EXPECT_NEAR(s.side[2], 5.0, 1e-12);
  EXPECT_EQ(s.opposite[0], 1);  // side 3 joins (0,0) and (0,3)
  EXPECT_EQ(s.opposite[1], 2);
  EXPECT_EQ(s.opposite[2], 0);
}

TEST(SortedSides, InvariantUnderRigidMotion) {
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-20, 20), ua(-M_PI, M_PI);
  for (int trial = 0; trial < 1000; ++trial) {
    const std::array<Eigen::Vector2d, 3> p = {
        Eigen::Vector2d(u(rng), u(rng)), Eigen::Vector2d(u(rng), u(rng)), Eigen::Vector2d(u(rng), u(rng))};
    const auto a = sorted_sides(p);
    const auto b = sorted_sides(moved(p, Pose2{u(rng), u(rng), ua(rng)}));
    for (size_t k = 0; k < 3; ++k) {
      ASSERT_NEAR(a.side[k], b.side[k], 1e-9);
      ASSERT_EQ(a.opposite[k], b.opposite[k]);
    }
  }
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
