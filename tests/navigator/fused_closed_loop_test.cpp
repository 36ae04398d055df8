// The whole motion loop in simulated time, without LCM: plant with wheel slip ->
// encoders -> odometry -> fusion with noisy laser fixes arriving 40 ms late ->
// navigator -> plant. Checks the TRUE pose error at each waypoint.

#include "mecanum_odometry/mecanum_odometry.hpp"
#include "navigator/navigator.hpp"
#include "pose_fusion/pose_fusion.hpp"
#include "robot_sim/encoder_model.hpp"
#include "robot_sim/mecanum_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <deque>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(FusedClosedLoop, NoisyDelayedFixesAndSlipStillReachWaypointsWithinFifteenMillimetres) {
  const RobotConfig robot;
  PlantConfig plant_config;
  plant_config.slip.spin_excess = {0.02, 0.0, 0.0, 0.0};  // one wheel slips 2 %
  plant_config.slip.lateral_noise_per_speed = 0.02;
  MecanumPlant plant(robot, plant_config, Pose2{}, 0);
  const EncoderModel encoders(robot.encoder_ticks_per_rev, 2'147'000'000);
  MecanumOdometry odometry(robot, OdometryConfig{});
  PoseFusion fusion{FusionConfig{}};
  Navigator nav{NavigatorConfig{}};
  std::mt19937 rng(3);
  std::normal_distribution<double> noise_xy(0.0, 0.005), noise_theta(0.0, 0.003);
  const Eigen::Matrix3d fix_covariance =
      Eigen::Vector3d(0.005 * 0.005, 0.005 * 0.005, 0.003 * 0.003).asDiagonal();

  NavGoal goal;
  goal.goal_id = 1;
  goal.waypoints = {
      {2.0, 0.0, 0.0}, {2.0, 1.5, deg_to_rad(90)}, {0.0, 1.0, deg_to_rad(180)}, {0.0, 0.0, 0.0}};
  nav.set_goal(goal, 0);

  std::deque<std::pair<int64_t, Pose2>> truth;
  std::vector<double> errors_xy, errors_heading;
  Pose2 previous_odometry;
  int64_t now = 0;
  int rejected = 0;
  while ((nav.status().state == NavState::kDriving || nav.status().state == NavState::kStoppedNoPose) &&
         now < 90'000'000) {
    now += 10'000;  // 100 Hz: encoders, odometry, fusion
    plant.advance_to(now);
    truth.emplace_back(now, plant.map_T_robot());
    if (truth.size() > 20) truth.pop_front();
    if (odometry.add_sample(now, encoders.counts(plant.wheel_angles())) == EncoderSampleResult::kIntegrated) {
      const Pose2 delta = previous_odometry.inverse() * odometry.estimate().odom_T_robot;
      fusion.add_odometry(now, delta, increment_covariance(delta, OdometryNoise{}));
    }
    previous_odometry = odometry.estimate().odom_T_robot;
    if (now % 40'000 == 0 && truth.size() > 4) {  // 25 Hz scans, delivered 40 ms after the fact
      const auto& [scan_time, scan_pose] = truth[truth.size() - 5];
      const Pose2 measured{scan_pose.x + noise_xy(rng), scan_pose.y + noise_xy(rng),
                           wrap_angle(scan_pose.theta + noise_theta(rng))};
      if (fusion.add_fix({scan_time, measured, fix_covariance, FixQuality::kGood}) ==
          FixResult::kRejectedGate) {
        ++rejected;
      }
    }
    if (now % 20'000 == 0) {  // 50 Hz control
      const FusionStatus status = fusion.status(now);
      nav.set_pose(fusion.estimate().map_T_robot, fusion.utime(),
                   status == FusionStatus::kOk ? PoseQuality::kGood : PoseQuality::kUnusable);
      const int before = nav.status().waypoints_reached;
      const BodyTwist cmd = nav.update(now);
      if (nav.status().waypoints_reached > before) {
        const Waypoint& w = goal.waypoints[static_cast<size_t>(before)];
        errors_xy.push_back(std::hypot(w.x - plant.map_T_robot().x, w.y - plant.map_T_robot().y));
        errors_heading.push_back(std::abs(angle_diff(w.theta, plant.map_T_robot().theta)));
      }
      plant.command(cmd, now);
    }
  }
  ASSERT_EQ(nav.status().state, NavState::kArrived)
      << to_string(nav.status().state) << " " << nav.status().reason;
  ASSERT_EQ(errors_xy.size(), goal.waypoints.size());
  std::printf("mission %.1f s, %d fixes gated out; true errors:", now * 1e-6, rejected);
  for (size_t i = 0; i < errors_xy.size(); ++i) {
    std::printf(" (%.1f mm, %.2f deg)", errors_xy[i] * 1e3, rad_to_deg(errors_heading[i]));
    EXPECT_LE(errors_xy[i], 0.015) << "waypoint " << i;
    EXPECT_LE(errors_heading[i], deg_to_rad(1.0)) << "waypoint " << i;
  }
  std::printf("\n");
  EXPECT_LE(rejected, 2);  // 99.9 % gate: consistent fixes pass
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
