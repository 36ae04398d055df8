// MissionMonitor, what refloc-mission records and decides without LCM: poses only while
// driving, the true error at each waypoint when the navigator reports it, the goal to
// send (and resend after a navigator restart), the timeout, odometry restarts, the NEES
// of the published covariances, pose_solver's range bias, and the report and summary the
// scripts read.

#include "mission_monitor.hpp"
#include "mission_summary.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

using ::testing::HasSubstr;
using ::testing::Not;

constexpr int64_t kSecond = 1'000'000;
const Eigen::Matrix3d kCovariance = Eigen::Vector3d(25e-6, 25e-6, 1e-4).asDiagonal();  // 5 mm, 10 mrad

Mission two_waypoints() {
  Mission m;
  m.waypoints = {{1.0, 0.0, 0.0}, {2.0, 1.0, M_PI / 2}};
  m.xy_tolerance_m = 0.02;
  m.timeout_s = 10.0;
  return m;
}

TEST(MissionMonitor, LocalizedByTheFirstOkPoseAndRecordsPosesOnlyWhileDriving) {
  MissionMonitor m(two_waypoints());
  m.on_pose(1, {0, 0, 0}, false, kCovariance);
  EXPECT_FALSE(m.localized());
  m.on_pose(2, {0, 0, 0}, true, kCovariance);
  EXPECT_TRUE(m.localized());
  m.on_ground_truth(2, {0, 0, 0});
  m.start_driving(10, 0);
  for (int64_t t = 10; t <= 20; t += 5) {
    m.on_ground_truth(t, {0.0, 0.0, 0.0});
    m.on_pose(t, {0.003, 0.004, 0.0}, true, kCovariance);     // 5 mm off: NEES 1
    m.on_laser_pose(t, {0.0, 0.0, 0.01}, true, kCovariance);  // 10 mrad: heading NEES 1
    m.on_laser_pose(t, {9.0, 9.0, 0.0}, false, kCovariance);  // not OK: not counted
  }
  m.stop_driving(20);
  const auto r = m.report("refloc.0");
  EXPECT_EQ(r["pose_samples"], 3);
  EXPECT_NEAR(r["pose_rmse_mm"].get<double>(), 5.0, 1e-9);
  EXPECT_EQ(r["laser_pose_samples"], 3);
  EXPECT_NEAR(r["laser_pose_rmse_mm"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(r["log_file"], "refloc.0");
  EXPECT_EQ(r["pose_nees"]["nees_fixes"], 3);
  EXPECT_NEAR(r["pose_nees"]["position_nees_mean"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(r["pose_nees"]["heading_nees_mean"].get<double>(), 0.0, 1e-9);
  EXPECT_EQ(r["laser_pose_nees"]["nees_fixes"], 3);
  EXPECT_NEAR(r["laser_pose_nees"]["position_nees_mean"].get<double>(), 0.0, 1e-9);
  EXPECT_NEAR(r["laser_pose_nees"]["heading_nees_mean"].get<double>(), 1.0, 1e-9);
  EXPECT_THAT(
      format_mission_summary(r),
      HasSubstr("POSE NEES vs GROUND_TRUTH: position 1.00 (honest: 2), 0.0 % outside 99 %; heading 0.00"));
}

TEST(MissionMonitor, ReportsPoseSolversLatestRangeBiasFromItsHeartbeat) {
  MissionMonitor m(two_waypoints());
  EXPECT_TRUE(m.report("")["range_bias_mm"].is_null()) << "never heard";
  EXPECT_THAT(format_mission_summary(m.report("")), Not(HasSubstr("range bias")));
  HeartbeatSample other;
  other.service = "pose_fusion";
  other.counters = {{"range_bias_um", 999}};
  m.on_heartbeat(other);
  EXPECT_TRUE(m.report("")["range_bias_mm"].is_null()) << "only pose_solver's gauge counts";
  HeartbeatSample solver;
  solver.service = "pose_solver";
  solver.counters = {{"scans", 10}, {"range_bias_um", 29'500}, {"range_bias_sigma_um", 400}};
  m.on_heartbeat(solver);
  solver.counters = {{"range_bias_um", -30'125}, {"range_bias_sigma_um", 350}};
  m.on_heartbeat(solver);
  const auto r = m.report("");
  EXPECT_NEAR(r["range_bias_mm"].get<double>(), -30.125, 1e-9);
  EXPECT_NEAR(r["range_bias_sigma_mm"].get<double>(), 0.35, 1e-9);
  EXPECT_THAT(format_mission_summary(r),
              HasSubstr("pose_solver range bias estimate: -30.1 mm (sigma 0.3 mm)"));
}

TEST(MissionMonitor, FirstGoalCarriesEveryWaypointAndTheMissionsTolerances) {
  MissionMonitor m(two_waypoints());
  m.start_driving(1000, 0);
  const auto g = m.goal_due(5000, 0);
  ASSERT_TRUE(g);
  EXPECT_FALSE(g->resend);
  EXPECT_EQ(g->utime, 5000);
  EXPECT_EQ(g->goal_id, 5000);
  EXPECT_EQ(g->first_waypoint, 0u);
  EXPECT_EQ(g->x_m, (std::vector<double>{1.0, 2.0}));
  EXPECT_EQ(g->y_m, (std::vector<double>{0.0, 1.0}));
  EXPECT_DOUBLE_EQ(g->theta_rad[1], M_PI / 2);
  EXPECT_DOUBLE_EQ(g->xy_tolerance_m, 0.02);
  EXPECT_FALSE(m.goal_due(5000, 1000)) << "not due again right away";
  EXPECT_EQ(format_goal_sent(*g, 2), "sent mission 5000\n");
}

TEST(MissionMonitor, ReachedWaypointGetsTheTrueErrorAtThatMoment) {
  MissionMonitor m(two_waypoints());
  m.start_driving(0, 0);
  const auto g = m.goal_due(100, 0);
  m.on_ground_truth(200, {1.003, -0.004, 0.01});
  const auto reached = m.on_status(g->goal_id, NavStatusState::kDriving, 1, "", kSecond / 10);
  ASSERT_EQ(reached, (std::vector<size_t>{0}));
  EXPECT_TRUE(m.result(0).reached);
  EXPECT_NEAR(m.result(0).error_xy_m, 0.005, 1e-12);
  EXPECT_NEAR(m.result(0).error_heading_rad, 0.01, 1e-12);
  EXPECT_FALSE(m.result(1).reached);
  EXPECT_EQ(format_waypoint_reached(0, m.result(0)), "waypoint 0 reached: true error 5.0 mm, 0.57 deg\n");
  EXPECT_TRUE(m.driving());
  m.on_ground_truth(300, {2.0, 1.0, M_PI / 2});
  EXPECT_EQ(m.on_status(g->goal_id, NavStatusState::kArrived, 2, "", kSecond / 5), (std::vector<size_t>{1}));
  EXPECT_FALSE(m.driving()) << "finished";
  EXPECT_TRUE(m.all_reached());
  m.stop_driving(400);
  const auto r = m.report("");
  EXPECT_EQ(r["waypoints_reached"], 2);
  EXPECT_NEAR(r["max_waypoint_error_mm"].get<double>(), 5.0, 1e-9);
  EXPECT_FALSE(r["aborted"].get<bool>());
  EXPECT_THAT(format_mission_summary(r),
              HasSubstr("waypoints reached: 2/2\nmax true waypoint error: 5.0 mm"));
}

TEST(MissionMonitor, StatusBeforeDrivingIsIgnored) {
  MissionMonitor m(two_waypoints());
  EXPECT_TRUE(m.on_status(1, NavStatusState::kArrived, 2, "", 0).empty());
  EXPECT_FALSE(m.result(0).reached);
}

TEST(MissionMonitor, RestartedNavigatorGetsTheRemainingWaypointsAsANewGoal) {
  MissionMonitor m(two_waypoints());
  m.start_driving(0, 0);
  const auto first = m.goal_due(100, 0);
  m.on_status(first->goal_id, NavStatusState::kDriving, 1, "", kSecond / 10);  // acknowledged, 1 reached
  m.on_status(0, NavStatusState::kIdle, 0, "", kSecond / 5);                   // restarted: forgot it
  const auto again = m.goal_due(200, kSecond / 2);
  ASSERT_TRUE(again);
  EXPECT_TRUE(again->resend);
  EXPECT_GT(again->goal_id, first->goal_id);
  EXPECT_EQ(again->first_waypoint, 1u);
  EXPECT_EQ(again->x_m, (std::vector<double>{2.0}));
  EXPECT_EQ(format_goal_sent(*again, 2), "resending waypoints 1..1 as goal " +
                                             std::to_string(again->goal_id) +
                                             " (navigator restarted or silent)\n");
  EXPECT_EQ(m.report("")["navigator_goal_losses"], 1);
}

TEST(MissionMonitor, DrivingLongerThanTheTimeoutAbortsWithTheReason) {
  MissionMonitor m(two_waypoints());  // timeout 10 s
  m.start_driving(0, 5 * kSecond);
  EXPECT_FALSE(m.timed_out(15 * kSecond));
  EXPECT_TRUE(m.timed_out(15 * kSecond + 1));
  EXPECT_FALSE(m.driving());
  m.stop_driving(11 * kSecond);
  const auto r = m.report("");
  EXPECT_TRUE(r["aborted"].get<bool>());
  EXPECT_EQ(r["abort_reason"], "timeout after 10 s");
  EXPECT_THAT(format_mission_summary(r), HasSubstr("ABORTED: timeout after 10 s"));
}

TEST(MissionMonitor, NavigatorAbortEndsTheMissionWithItsReason) {
  MissionMonitor m(two_waypoints());
  m.start_driving(0, 0);
  const auto g = m.goal_due(100, 0);
  m.on_status(g->goal_id, NavStatusState::kAborted, 0, "no pose", kSecond / 10);
  EXPECT_FALSE(m.driving());
  EXPECT_EQ(m.report("")["abort_reason"], "navigator aborted: no pose");
}

TEST(MissionMonitor, LocalizationTimeoutCountsFromTheStartOfWaiting) {
  Mission mission = two_waypoints();
  mission.localization_timeout_s = 2.0;
  MissionMonitor m(mission);
  m.start_waiting(kSecond);
  EXPECT_FALSE(m.localization_timed_out(3 * kSecond));
  EXPECT_TRUE(m.localization_timed_out(3 * kSecond + 1));
}

TEST(MissionMonitor, OdometryDriftIsMeasuredOverTheLatestOdometryFrame) {
  MissionMonitor m(two_waypoints());
  for (int64_t t = 0; t <= 400; t += 50) m.on_ground_truth(t, {static_cast<double>(t) * 0.001, 0.0, 0.0});
  m.start_driving(0, 0);
  m.on_odometry(0, {5.0, 5.0, 0.0}, 0.0);
  m.on_odometry(100, {5.1, 5.0, 0.0}, 0.1);
  m.on_odometry(200, {0.0, 0.0, 0.0}, 0.0);    // restarted: distance went back
  m.on_odometry(400, {0.21, 0.0, 0.0}, 0.21);  // truth moved 0.2 m: 10 mm drift
  m.stop_driving(400);
  const auto r = m.report("");
  EXPECT_EQ(r["odometry_restarts"], 1);
  EXPECT_NEAR(r["odometry_drift_mm"].get<double>(), 10.0, 1e-6);
  EXPECT_THAT(format_mission_summary(r), HasSubstr("10.0 mm (since the last odometry restart)"));
}

TEST(MissionMonitor, TraceHasTruthEstimatesWithTheirErrorsAndWaypointArrivals) {
  MissionMonitor m(two_waypoints());
  m.on_ground_truth(5, {0.0, 0.0, 0.0});  // before driving: not in the trace
  m.start_driving(10, 0);
  m.on_ground_truth(10, {0.0, 0.0, 0.0});
  m.on_ground_truth(30, {1.0, 0.0, 0.0});
  m.on_pose(20, {0.5, 0.003, 0.0}, true, kCovariance);          // truth at 20: (0.5, 0): 3 mm
  m.on_laser_pose(20, {0.504, 0.003, 0.0}, true, kCovariance);  // 5 mm
  const auto goal = m.goal_due(30, 0);
  ASSERT_TRUE(goal);
  m.on_status(goal->goal_id, NavStatusState::kDriving, 1, "", 0);
  m.stop_driving(40);
  const PathTrace trace = m.path_trace();
  EXPECT_EQ(trace.start_utime, 10);
  ASSERT_EQ(trace.samples.size(), 4u);
  EXPECT_EQ(trace.samples[0].channel, "GROUND_TRUTH");
  EXPECT_EQ(trace.samples[0].utime, 10);
  EXPECT_EQ(trace.samples[2].channel, "POSE");
  EXPECT_NEAR(trace.samples[2].error_m, 0.003, 1e-9);
  EXPECT_EQ(trace.samples[3].channel, "LASER_POSE");
  EXPECT_NEAR(trace.samples[3].error_m, 0.005, 1e-9);
  ASSERT_EQ(trace.waypoints.size(), 2u);
  EXPECT_TRUE(trace.waypoints[0].reached);
  EXPECT_EQ(trace.waypoints[0].reached_utime, 30);  // the truth it was judged by
  EXPECT_NEAR(trace.waypoints[0].error_m, 0.0, 1e-12);
  EXPECT_FALSE(trace.waypoints[1].reached);
  EXPECT_DOUBLE_EQ(trace.waypoints[1].target.x, 2.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
