#include "drive_path.hpp"

#include "common/angles.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// The pose dt later by holding the state's body twist (exact on a leg and inside a corner).
Pose2 advanced(const DriveState& s, double dt) { return s.map_T_robot * se2_exp(s.twist, dt); }

TEST(DrivePath, DemoLoopIsFortyOnePointFourMetresAndClosesOnItself) {
  const DrivePath path = DrivePath::demo_hall_loop(0.8, DrivePath::Heading::kTangent);
  EXPECT_NEAR(path.lap_length(), 2 * 12.0 + 2 * 4.0 + 2 * M_PI * 1.5, 1e-12);
  const double lap_s = path.lap_length() / 0.8;
  EXPECT_TRUE(approx_equal(path.at(0.0).map_T_robot, {4.0, 2.5, 0.0}, 1e-12, 1e-12));
  EXPECT_TRUE(approx_equal(path.at(lap_s).map_T_robot, path.at(0.0).map_T_robot, 1e-9, 1e-9));
}

TEST(DrivePath, EveryStateMovesByItsOwnTwistOnLegsAndInCorners) {
  for (DrivePath::Heading heading : {DrivePath::Heading::kTangent, DrivePath::Heading::kFixed}) {
    const DrivePath path = DrivePath::demo_hall_loop(0.8, heading);
    int checked = 0;
    for (double t = 0.0; t < 52.0; t += 0.37) {
      const DriveState s = path.at(t);
      EXPECT_NEAR(std::hypot(s.twist.vx, s.twist.vy), 0.8, 1e-12);
      const Pose2 next = path.at(t + 0.005).map_T_robot;
      // Away from a leg/corner joint the 5 ms step is exact; at a joint it is off by far less than 1 mm.
      EXPECT_TRUE(approx_equal(advanced(s, 0.005), next, 1e-4, 1e-3)) << t;
      const Eigen::Vector2d moved = next.translation() - s.map_T_robot.translation();
      EXPECT_GT(moved.normalized().dot(s.map_direction), 0.999) << t;
      ++checked;
    }
    EXPECT_EQ(checked, 141);
  }
}

TEST(DrivePath, CornersTurnAtSpeedOverRadiusWhenFacingTheWayDriven) {
  const DrivePath tangent = DrivePath::demo_hall_loop(0.8, DrivePath::Heading::kTangent);
  const double in_first_corner = (12.0 + 1.0) / 0.8;
  EXPECT_NEAR(tangent.at(in_first_corner).twist.wz, 0.8 / 1.5, 1e-12);
  EXPECT_DOUBLE_EQ(tangent.at(1.0).twist.wz, 0.0);
  const DrivePath crab = DrivePath::demo_hall_loop(0.8, DrivePath::Heading::kFixed);
  const DriveState up_the_right_leg = crab.at((12.0 + 0.75 * M_PI + 2.0) / 0.8);
  EXPECT_NEAR(up_the_right_leg.twist.vx, 0.0, 1e-12);
  EXPECT_NEAR(up_the_right_leg.twist.vy, 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(up_the_right_leg.map_T_robot.theta, 0.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
