// refloc-mission's MissionProgress: a restarted navigator forgets its goal; the
// mission resends the remaining waypoints under a new id and keeps counting.
#include "mission_progress.hpp"

#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kS = 1'000'000;

TEST(MissionProgress, SendsOnceThenResendsEverySecondUntilAcknowledged) {
  MissionProgress p(3);
  EXPECT_TRUE(p.needs_send(0));
  EXPECT_EQ(p.start_goal(100, 0), 100);
  EXPECT_FALSE(p.needs_send(kS / 2));
  EXPECT_TRUE(p.needs_send(kS));
  p.on_status(100, NavStatusState::kDriving, 0, kS + 1);
  EXPECT_FALSE(p.needs_send(kS + 2));
  EXPECT_EQ(p.goals_lost(), 0);
}

TEST(MissionProgress, CountsReachedWaypointsAndFinishesOnArrival) {
  MissionProgress p(3);
  p.start_goal(7, 0);
  EXPECT_EQ(p.on_status(7, NavStatusState::kDriving, 1, 1), 1U);
  EXPECT_EQ(p.on_status(7, NavStatusState::kDriving, 1, 2), 0U);
  EXPECT_EQ(p.on_status(7, NavStatusState::kArrived, 3, 3), 2U);
  EXPECT_TRUE(p.finished());
  EXPECT_FALSE(p.aborted());
  EXPECT_FALSE(p.needs_send(10 * kS));
}

TEST(MissionProgress, NavigatorRestartReportingIdleResendsTheRemainingWaypointsUnderANewId) {
  MissionProgress p(4);
  p.start_goal(50, 0);
  p.on_status(50, NavStatusState::kDriving, 2, kS);
  // The restarted navigator: IDLE, no goal.
  EXPECT_EQ(p.on_status(0, NavStatusState::kIdle, 0, 2 * kS), 0U);
  EXPECT_EQ(p.goals_lost(), 1);
  EXPECT_TRUE(p.needs_send(2 * kS + 300'000));
  const int64_t id = p.start_goal(50, 2 * kS + 300'000);  // clock gave the same id: made unique
  EXPECT_EQ(id, 51);
  EXPECT_EQ(p.first_waypoint(), 2U);
  EXPECT_EQ(p.resends(), 1);
  // A late status of the old goal is not progress of the new one.
  EXPECT_EQ(p.on_status(50, NavStatusState::kDriving, 3, 2 * kS + 310'000), 0U);
  // The new goal's waypoint 1 is the mission's waypoint 3.
  EXPECT_EQ(p.on_status(51, NavStatusState::kDriving, 1, 3 * kS), 1U);
  EXPECT_EQ(p.reached(), 3U);
  EXPECT_EQ(p.on_status(51, NavStatusState::kArrived, 2, 4 * kS), 1U);
  EXPECT_TRUE(p.finished());
}

TEST(MissionProgress, IdleBeforeTheGoalIsAcknowledgedIsNotALostGoal) {
  MissionProgress p(2);
  p.start_goal(9, 0);
  p.on_status(0, NavStatusState::kIdle, 0, 10);  // the navigator has not read the goal yet
  EXPECT_EQ(p.goals_lost(), 0);
  EXPECT_FALSE(p.needs_send(500'000));
}

TEST(MissionProgress, AnotherSendersActiveGoalIsLeftAlone) {
  MissionProgress p(2);
  p.start_goal(9, 0);
  p.on_status(9, NavStatusState::kDriving, 0, 10);
  p.on_status(1234, NavStatusState::kDriving, 0, 20);
  EXPECT_EQ(p.goals_lost(), 0);
  EXPECT_FALSE(p.needs_send(30));
}

TEST(MissionProgress, SilentNavigatorAfterAcknowledgementGetsTheGoalAgainAfterTheTimeout) {
  MissionProgress p(2);
  p.start_goal(9, 0);
  p.on_status(9, NavStatusState::kDriving, 0, kS);
  EXPECT_FALSE(p.needs_send(2 * kS));
  EXPECT_TRUE(p.needs_send(3 * kS));
}

TEST(MissionProgress, AbortEndsTheMission) {
  MissionProgress p(2);
  p.start_goal(9, 0);
  p.on_status(9, NavStatusState::kAborted, 0, 10);
  EXPECT_TRUE(p.aborted());
  EXPECT_TRUE(p.finished());
  EXPECT_FALSE(p.needs_send(10 * kS));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
