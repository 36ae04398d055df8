// The navigator facing hostile or broken peers: NAV_GOAL and POSE with NaN/inf/1e300
// in every consumed field, POSE stamps an hour off or at the int64 limits. CMD_VEL is
// never non-finite nor above the limits, every refusal is counted, and the node keeps
// driving on good input after.

#include "navigator/navigator_input_checks.hpp"
#include "navigator/navigator_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;  // a plausible wall-clock time [us]
constexpr int64_t kPeriod = 20'000;             // 50 Hz control, POSE at the same rate here
constexpr int64_t kHour = 3'600'000'000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

NavGoal goal_to(double x) {
  NavGoal goal;
  goal.goal_id = 3;
  goal.waypoints = {{x, 0.0, 0.0}};
  return goal;
}

bool finite_within_limits(const BodyTwist& c, const NavigatorConfig& config) {
  return std::isfinite(c.vx) && std::isfinite(c.vy) && std::isfinite(c.wz) &&
         std::hypot(c.vx, c.vy) <= config.translation.max_speed + 1e-12 &&
         std::abs(c.wz) <= config.rotation.max_speed + 1e-12;
}

/// Ticks [from, to) with a good pose at the origin before each; the last command's vx.
double drive(NavigatorNode& node, int from, int to) {
  double vx = 0.0;
  for (int k = from; k < to; ++k) {
    const int64_t t = kT0 + k * kPeriod;
    node.on_pose({}, t - 5'000, PoseQuality::kGood, t);
    const NavigatorOutput out = node.on_control_tick(t);
    if (out.command) {
      EXPECT_TRUE(finite_within_limits(*out.command, NavigatorConfig{}));
      vx = out.command->vx;
    }
  }
  return vx;
}

TEST(NavigatorHostileInput, GoalWithNonFiniteOrAbsurdNumbersIsRefusedCountedAndTheNextGoodOneDriven) {
  const std::vector<std::pair<std::string, std::function<void(NavGoal&, double)>>> fields = {
      {"x", [](NavGoal& g, double v) { g.waypoints[0].x = v; }},
      {"y", [](NavGoal& g, double v) { g.waypoints[0].y = v; }},
      {"theta", [](NavGoal& g, double v) { g.waypoints[0].theta = v; }},
      {"xy_tolerance", [](NavGoal& g, double v) { g.xy_tolerance = v; }},
      {"heading_tolerance", [](NavGoal& g, double v) { g.heading_tolerance = v; }},
      {"max_speed", [](NavGoal& g, double v) { g.max_speed = v; }},
  };
  for (const auto& [name, set] : fields) {
    for (const double bad : {kNaN, kInf, -kInf, 1e300, -1e300}) {
      const bool tolerance_or_speed =
          name == "xy_tolerance" || name == "heading_tolerance" || name == "max_speed";
      if (bad == -1e300 && tolerance_or_speed) continue;  // <= 0 means "the default": legitimate
      const std::string what = name + " = " + std::to_string(bad);
      NavigatorNode node{NavigatorConfig{}};
      NavGoal goal = goal_to(2.0);
      set(goal, bad);
      const NavigatorOutput out = node.on_goal(goal, kT0);
      ASSERT_NE(out.status, nullptr) << what;
      EXPECT_EQ(out.status->state, NavState::kAborted) << what;
      EXPECT_EQ(count(node.events(), "goals_refused"), 1) << what;
      EXPECT_EQ(count(node.events(),
                      std::isfinite(bad) ? "rejected_nav_goal_out_of_bounds" : "rejected_nav_goal_nonfinite"),
                1)
          << what;
      EXPECT_EQ(drive(node, 1, 10), 0.0) << what;  // nothing to drive to
      node.on_goal(goal_to(2.0), kT0 + 10 * kPeriod);
      EXPECT_GT(drive(node, 11, 30), 0.0) << what;
    }
  }
}

TEST(NavigatorHostileInput, ABrokenGoalWhileDrivingIsRefusedAndTheActiveGoalGoesOn) {
  NavigatorNode node{NavigatorConfig{}};
  node.on_goal(goal_to(2.0), kT0);
  ASSERT_GT(drive(node, 1, 10), 0.0);
  NavGoal hostile = goal_to(2.0);  // the active goal's own id, as a copy-and-poison peer sends it
  hostile.xy_tolerance = kNaN;
  const NavigatorOutput out = node.on_goal(hostile, kT0 + 10 * kPeriod);
  EXPECT_EQ(out.status, nullptr) << "no status for the refused goal: it would read as the active one's";
  EXPECT_EQ(count(node.events(), "goals_refused"), 1);
  EXPECT_EQ(count(node.events(), "rejected_nav_goal_nonfinite"), 1);
  EXPECT_GT(drive(node, 11, 20), 0.0) << "the active goal is still driven";
}

TEST(NavigatorHostileInput, PoseWithNonFiniteOrAbsurdValuesIsRefusedAndTheRobotStopsWhenNoGoodOneFollows) {
  for (const double bad : {kNaN, kInf, -kInf, 1e300, -1e300}) {
    for (int field = 0; field < 3; ++field) {
      NavigatorNode node{NavigatorConfig{}};
      node.on_goal(goal_to(2.0), kT0);
      ASSERT_GT(drive(node, 1, 20), 0.0);
      Pose2 pose;
      (field == 0 ? pose.x : field == 1 ? pose.y : pose.theta) = bad;
      // Only bad poses from now on: refused, the last good one ages out, the robot stops.
      BodyTwist last;
      for (int k = 20; k < 40; ++k) {
        const int64_t t = kT0 + k * kPeriod;
        node.on_pose(pose, t - 5'000, PoseQuality::kGood, t);
        EXPECT_EQ(count(node.events(),
                        std::isfinite(bad) ? "rejected_pose_out_of_bounds" : "rejected_pose_nonfinite"),
                  1);
        const NavigatorOutput out = node.on_control_tick(t);
        ASSERT_TRUE(out.command);
        EXPECT_TRUE(finite_within_limits(*out.command, NavigatorConfig{}));
        last = *out.command;
      }
      EXPECT_EQ(last.vx, 0.0);
      EXPECT_EQ(node.navigator().status().state, NavState::kStoppedNoPose);
      EXPECT_GT(drive(node, 40, 60), 0.0);  // good poses again: driving again
    }
  }
}

TEST(NavigatorHostileInput, PoseStampedFarOffIsRefusedAndCannotKeepAStalePoseFresh) {
  const std::vector<std::pair<int64_t, std::string>> stamps = {
      {kT0 + 20 * kPeriod + kHour, "rejected_pose_stamp_ahead"},
      {std::numeric_limits<int64_t>::max(), "rejected_pose_stamp_ahead"},
      {0, "rejected_pose_stamp_behind"},
      {kT0 - kHour, "rejected_pose_stamp_behind"},
      {std::numeric_limits<int64_t>::min(), "rejected_pose_stamp_behind"},
      {-kHour, "rejected_pose_stamp_behind"},
  };
  for (const auto& [stamp, counter] : stamps) {
    NavigatorNode node{NavigatorConfig{}};
    node.on_goal(goal_to(2.0), kT0);
    ASSERT_GT(drive(node, 1, 20), 0.0);
    const int64_t t = kT0 + 20 * kPeriod;
    node.on_pose({}, stamp, PoseQuality::kGood, t);
    EXPECT_EQ(count(node.events(), counter), 1) << stamp;
    // No pose after it: the one stamped an hour ahead must not count as fresh.
    const NavigatorOutput out = node.on_control_tick(t + 1'000'000);
    ASSERT_TRUE(out.command);
    EXPECT_EQ(out.command->vx, 0.0) << stamp;
    EXPECT_GT(drive(node, 71, 90), 0.0) << stamp;
  }
}

TEST(NavigatorHostileInput, AFutureStampedPoseIsNotFreshEvenInsideTheNavigator) {
  Navigator nav{NavigatorConfig{}};
  nav.set_goal(goal_to(2.0), kT0);
  nav.set_pose({}, kT0 + kHour, PoseQuality::kGood);
  EXPECT_EQ(nav.update(kT0 + kPeriod).vx, 0.0);
  EXPECT_EQ(nav.status().state, NavState::kStoppedNoPose);
  EXPECT_NE(nav.status().reason.find("in the future"), std::string::npos);
}

TEST(BoundedCommand, NonFiniteBecomesZeroAndTooFastIsClampedKeepingItsDirection) {
  bool changed = false;
  const BodyTwist zero = bounded_command({kNaN, 0.1, 0.0}, 1.0, 1.0, changed);
  EXPECT_TRUE(changed);
  EXPECT_EQ(zero.vx, 0.0);
  EXPECT_EQ(zero.vy, 0.0);
  const BodyTwist fast = bounded_command({1e308, 1e308, -1e308}, 1.0, 0.5, changed);
  EXPECT_TRUE(changed);
  EXPECT_NEAR(fast.vx, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(fast.vy, std::sqrt(0.5), 1e-12);
  EXPECT_EQ(fast.wz, -0.5);
  const BodyTwist fine = bounded_command({0.3, -0.2, 0.1}, 1.0, 1.0, changed);
  EXPECT_FALSE(changed);
  EXPECT_EQ(fine.vx, 0.3);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
