#include "navigator/navigator.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 10'000'000;
constexpr int64_t kPeriod = 20'000;

NavGoal goal_to(double x, double y, double theta) {
  NavGoal goal;
  goal.goal_id = 7;
  goal.waypoints = {{x, y, theta}};
  return goal;
}

bool is_zero(const BodyTwist& c) { return c.vx == 0.0 && c.vy == 0.0 && c.wz == 0.0; }

TEST(Navigator, IdleWithoutGoalCommandsZero) {
  Navigator nav{NavigatorConfig{}};
  nav.set_pose({}, kT0, PoseQuality::kGood);
  EXPECT_TRUE(is_zero(nav.update(kT0)));
  EXPECT_EQ(nav.status().state, NavState::kIdle);
}

TEST(Navigator, StalePoseGivesZeroTwistWithinOneControlPeriodAndDrivingResumes) {
  Navigator nav{NavigatorConfig{}};
  nav.set_goal(goal_to(2.0, 0.0, 0.0), kT0);
  nav.set_pose({}, kT0, PoseQuality::kGood);
  int64_t now = kT0;
  for (int i = 0; i < 10; ++i) nav.update(now += kPeriod);  // t0 + 200 ms: pose exactly at the limit
  EXPECT_GT(nav.update(now).vx, 0.0);
  EXPECT_EQ(nav.status().state, NavState::kDriving);
  // The first period after the pose turns 200 ms old commands zero.
  const BodyTwist stopped = nav.update(now += kPeriod);
  EXPECT_LE(now - kT0, 200'000 + kPeriod);
  EXPECT_TRUE(is_zero(stopped));
  EXPECT_EQ(nav.status().state, NavState::kStoppedNoPose);
  EXPECT_NE(nav.status().reason.find("220 ms old"), std::string::npos) << nav.status().reason;
  // A good pose again: driving resumes, ramping up from zero under max_accel.
  nav.set_pose({0.1, 0.0, 0.0}, now, PoseQuality::kGood);
  const BodyTwist resumed = nav.update(now += kPeriod);
  EXPECT_EQ(nav.status().state, NavState::kDriving);
  EXPECT_NEAR(resumed.vx, 0.5 * 0.02, 1e-12);
}

TEST(Navigator, PoseNotOkStopsImmediately) {
  Navigator nav{NavigatorConfig{}};
  nav.set_goal(goal_to(2.0, 0.0, 0.0), kT0);
  nav.set_pose({}, kT0, PoseQuality::kGood);
  EXPECT_GT(nav.update(kT0 + kPeriod).vx, 0.0);
  nav.set_pose({}, kT0 + kPeriod, PoseQuality::kUnusable);
  EXPECT_TRUE(is_zero(nav.update(kT0 + 2 * kPeriod)));
  EXPECT_EQ(nav.status().state, NavState::kStoppedNoPose);
  nav.set_pose({}, kT0 + 2 * kPeriod, PoseQuality::kDegraded);
  EXPECT_TRUE(is_zero(nav.update(kT0 + 3 * kPeriod)));  // degraded refused by default
}

TEST(Navigator, CommandIsExpressedInTheBodyFrame) {
  Navigator nav{NavigatorConfig{}};
  nav.set_goal(goal_to(2.0, 0.0, M_PI / 2.0), kT0);
  nav.set_pose({0.0, 0.0, M_PI / 2.0}, kT0, PoseQuality::kGood);  // facing +y
  const BodyTwist c = nav.update(kT0 + kPeriod);
  EXPECT_NEAR(c.vx, 0.0, 1e-12);
  EXPECT_NEAR(c.vy, -0.01, 1e-12);  // the target is on the robot's right
  EXPECT_NEAR(c.wz, 0.0, 1e-12);
}

TEST(Navigator, EmptyGoalCancelsAndInvalidGoalIsAborted) {
  Navigator nav{NavigatorConfig{}};
  nav.set_pose({}, kT0, PoseQuality::kGood);
  nav.set_goal(goal_to(2.0, 0.0, 0.0), kT0);
  nav.update(kT0 + kPeriod);
  NavGoal cancel;
  cancel.goal_id = 8;
  nav.set_goal(cancel, kT0 + kPeriod);
  EXPECT_EQ(nav.status().state, NavState::kAborted);
  EXPECT_NE(nav.status().reason.find("cancelled"), std::string::npos);
  EXPECT_TRUE(is_zero(nav.update(kT0 + 2 * kPeriod)));
  nav.set_goal(goal_to(NAN, 0.0, 0.0), kT0);
  EXPECT_EQ(nav.status().state, NavState::kAborted);
  EXPECT_EQ(nav.status().reason, "invalid goal: waypoint 0 is not finite");
}

TEST(Navigator, RepublishedGoalDoesNotRestartTheMission) {
  Navigator nav{NavigatorConfig{}};
  NavGoal goal = goal_to(0.0, 0.0, 0.0);
  goal.waypoints.push_back({1.0, 0.0, 0.0});
  nav.set_goal(goal, kT0);
  int64_t now = kT0;
  for (int i = 0; i < 20; ++i) {  // at the first waypoint already: settles in 0.2 s
    nav.set_pose({}, now, PoseQuality::kGood);
    nav.update(now += kPeriod);
  }
  ASSERT_EQ(nav.status().waypoints_reached, 1);
  EXPECT_FALSE(nav.set_goal(goal, now));
  EXPECT_EQ(nav.status().waypoints_reached, 1);
  goal.waypoints[1].x = 2.0;  // same id, new content: a new mission
  EXPECT_TRUE(nav.set_goal(goal, now));
  EXPECT_EQ(nav.status().waypoints_reached, 0);
}

TEST(Navigator, NoProgressAbortsAfterTheTimeout) {
  NavigatorConfig config;
  config.progress_timeout = 2.0;
  Navigator nav{config};
  nav.set_goal(goal_to(1.0, 0.0, 0.0), kT0);
  int64_t now = kT0;
  for (int i = 0; i < 150; ++i) {  // the robot is stuck: the pose never changes
    nav.set_pose({}, now, PoseQuality::kGood);
    nav.update(now += kPeriod);
  }
  EXPECT_EQ(nav.status().state, NavState::kAborted);
  EXPECT_NE(nav.status().reason.find("no progress"), std::string::npos);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
