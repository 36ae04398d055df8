// refloc-status's pose line: the last POSE with its 1-sigma, staleness, and laser fixes per
// second from LASER_POSE receive times (a fake clock: the times are arguments).

#include "pose_watch.hpp"

#include <gtest/gtest.h>
#include <refloc/pose2d_t.hpp>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

PoseSample pose_with_covariance(double var_x, double var_y, double cov_xy, double var_theta) {
  PoseSample p;
  p.x_m = 2.0;
  p.y_m = -1.0;
  p.theta_rad = -M_PI / 2;
  p.covariance = {var_x, cov_xy, 0.0, cov_xy, var_y, 0.0, 0.0, 0.0, var_theta};
  p.status = pose2d_t::STATUS_DEGRADED;
  return p;
}

TEST(PoseWatch, SigmaIsTheWorstDirectionOfThePositionCovariance) {
  PoseWatch watch(0.0, 3.0);
  watch.on_pose(pose_with_covariance(9e-6, 1e-6, 0.0, 1e-6), 1.0);
  PoseReport r = watch.report(1.5);
  EXPECT_NEAR(r.sigma_position_m, 0.003, 1e-12);
  EXPECT_NEAR(r.sigma_theta_rad, 0.001, 1e-12);
  EXPECT_NEAR(r.age_s, 0.5, 1e-12);
  EXPECT_FALSE(r.stale);
  watch.on_pose(pose_with_covariance(5e-6, 5e-6, 4e-6, NAN), 2.0);  // eigenvalues 9e-6 and 1e-6
  r = watch.report(2.0);
  EXPECT_NEAR(r.sigma_position_m, 0.003, 1e-12);
  EXPECT_LT(r.sigma_theta_rad, 0.0) << "not a variance: unusable, not a number";
  EXPECT_TRUE(watch.report(5.1).stale);
}

TEST(PoseWatch, FixesPerSecondOverTheLastTwoSecondsOrSinceListeningBegan) {
  PoseWatch watch(10.0, 3.0, 2.0);
  for (int i = 0; i < 10; ++i) watch.on_laser_pose(i % 5 == 4 ? pose2d_t::STATUS_LOST : 0, 10.0 + 0.1 * i);
  PoseReport r = watch.report(11.0);  // 1 s of listening: 10 fixes, 8 OK
  EXPECT_NEAR(r.laser_poses_per_s, 10.0, 1e-9);
  EXPECT_NEAR(r.fixes_ok_per_s, 8.0, 1e-9);
  for (int i = 10; i < 30; ++i) watch.on_laser_pose(0, 10.0 + 0.1 * i);
  r = watch.report(13.0);  // window (11, 13]: 20 fixes
  EXPECT_NEAR(r.laser_poses_per_s, 10.0, 1e-9);
  EXPECT_NEAR(r.fixes_ok_per_s, 10.0, 1e-9);
  EXPECT_NEAR(watch.report(20.0).laser_poses_per_s, 0.0, 1e-9) << "fixes stopped: the rate falls to 0";
}

TEST(PoseWatch, LineNamesStatusPositionHeadingSigmaAndFixes) {
  PoseWatch watch(0.0, 3.0);
  EXPECT_EQ(format_pose_line(watch.report(1.0)), "POSE none heard, fixes 0.0/s OK of 0.0/s\n");
  watch.on_pose(pose_with_covariance(9e-6, 1e-6, 0.0, 1e-6), 1.0);
  EXPECT_EQ(
      format_pose_line(watch.report(1.0)),
      "POSE DEGRADED x 2.000 y -1.000 m, theta -90.00 deg, sigma 3.0 mm 0.06 deg, fixes 0.0/s OK of 0.0/s\n");
  EXPECT_EQ(format_pose_line(watch.report(5.5)).rfind("POSE STALE (DEGRADED 4.5 s ago) x 2.000 y", 0), 0u);
}

TEST(PoseStatusName, MatchesPoseTypeConstants) {
  EXPECT_EQ(pose_status_name(pose2d_t::STATUS_OK), "OK");
  EXPECT_EQ(pose_status_name(pose2d_t::STATUS_DEGRADED), "DEGRADED");
  EXPECT_EQ(pose_status_name(pose2d_t::STATUS_LOST), "LOST");
  EXPECT_EQ(pose_status_name(pose2d_t::STATUS_AMBIGUOUS), "AMBIGUOUS");
  EXPECT_EQ(pose_status_name(pose2d_t::STATUS_INITIALIZING), "INITIALIZING");
  EXPECT_EQ(pose_status_name(9), "STATUS_9");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
