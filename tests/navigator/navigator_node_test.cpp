// NavigatorNode: what the navigator service publishes and counts per goal, control
// tick and status tick (the decisions its main used to make).

#include "navigator/navigator_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 10'000'000;
constexpr int64_t kPeriod = 20'000;  // 50 Hz control

NavGoal goal_to(double x, int64_t id = 7) {
  NavGoal goal;
  goal.goal_id = id;
  goal.waypoints = {{x, 0.0, 0.0}};
  return goal;
}

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

TEST(NavigatorNode, NoCommandsWithoutAGoalButAStatusOnFirstTick) {
  NavigatorNode node{NavigatorConfig{}};
  const NavigatorOutput first = node.on_control_tick(kT0);
  EXPECT_FALSE(first.command);  // never active: silent, teleoperation may drive
  ASSERT_NE(first.status, nullptr);
  EXPECT_EQ(first.status->state, NavState::kIdle);
  ASSERT_EQ(node.events().size(), 1u);
  EXPECT_EQ(node.events()[0].log, "goal 0: IDLE (waypoint 0/0)");
  EXPECT_EQ(node.on_control_tick(kT0 + kPeriod).status, nullptr);  // unchanged
  EXPECT_NE(node.on_status_tick().status, nullptr);                // the periodic one regardless
  EXPECT_TRUE(node.events().empty());
}

TEST(NavigatorNode, NewGoalIsPublishedAndARepublishedOneIgnored) {
  NavigatorNode node{NavigatorConfig{}};
  const NavigatorOutput started = node.on_goal(goal_to(2.0), kT0);
  ASSERT_NE(started.status, nullptr);
  EXPECT_EQ(started.status->state, NavState::kDriving);
  EXPECT_EQ(started.status->goal_id, 7);
  const NavigatorOutput again = node.on_goal(goal_to(2.0), kT0 + kPeriod);
  EXPECT_EQ(again.status, nullptr);
  EXPECT_TRUE(node.events().empty());
}

TEST(NavigatorNode, InvalidGoalIsCountedAsRefused) {
  NavigatorNode node{NavigatorConfig{}};
  const NavigatorOutput refused = node.on_goal(goal_to(std::numeric_limits<double>::quiet_NaN()), kT0);
  ASSERT_NE(refused.status, nullptr);
  EXPECT_EQ(refused.status->state, NavState::kAborted);
  EXPECT_EQ(count(node.events(), "goals_refused"), 1);
}

TEST(NavigatorNode, LosingThePoseStopsOnceCountedAndDegradesTheHeartbeat) {
  NavigatorNode node{NavigatorConfig{}};
  node.on_goal(goal_to(2.0), kT0);
  node.on_pose({}, kT0, PoseQuality::kGood, kT0);
  const NavigatorOutput driving = node.on_control_tick(kT0 + kPeriod);
  ASSERT_TRUE(driving.command);
  EXPECT_GT(driving.command->vx, 0.0);
  EXPECT_TRUE(node.health().ok);
  node.on_pose({}, kT0 + kPeriod, PoseQuality::kUnusable, kT0 + kPeriod);
  const NavigatorOutput stopped = node.on_control_tick(kT0 + 2 * kPeriod);
  ASSERT_TRUE(stopped.command);
  EXPECT_EQ(stopped.command->vx, 0.0);
  EXPECT_EQ(count(node.events(), "pose_stops"), 1);
  EXPECT_FALSE(node.health().ok);
  EXPECT_EQ(node.health().detail, node.navigator().status().reason);
  EXPECT_FALSE(node.health().detail.empty());
  node.on_control_tick(kT0 + 3 * kPeriod);
  EXPECT_EQ(count(node.events(), "pose_stops"), 0);  // counted on entering the stop only
}

TEST(NavigatorNode, CommandsContinueHalfASecondAfterTheGoalEnds) {
  NavigatorNode node{NavigatorConfig{}};
  node.on_goal(goal_to(2.0), kT0);
  node.on_pose({}, kT0, PoseQuality::kGood, kT0);
  node.on_control_tick(kT0 + kPeriod);
  const NavigatorOutput cancelled = node.on_goal(NavGoal{8, {}, 0.0, 0.0, 0.0}, kT0 + 2 * kPeriod);
  ASSERT_NE(cancelled.status, nullptr);
  EXPECT_EQ(cancelled.status->state, NavState::kAborted);
  const int64_t last_active = kT0 + kPeriod;
  EXPECT_TRUE(node.on_control_tick(last_active + NavigatorNode::kCommandHoldUs).command);
  EXPECT_EQ(node.on_control_tick(last_active + NavigatorNode::kCommandHoldUs).command->vx, 0.0);
  EXPECT_FALSE(node.on_control_tick(last_active + NavigatorNode::kCommandHoldUs + 1).command);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
