// The navigator driving the simulated Mecanum base with a perfect pose: the
// whole control loop without LCM, in simulated time.

#include "navigator/navigator.hpp"
#include "robot_sim/mecanum_plant.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

struct ReachedError {
  double xy = 0.0;       ///< [m]
  double heading = 0.0;  ///< [rad]
};

TEST(NavigatorClosedLoop, ReachesSixWaypointsWithinTenMillimetresAndHalfADegree) {
  const RobotConfig robot;
  MecanumPlant plant(robot, PlantConfig{}, Pose2{0.0, 0.0, 0.0}, 0);
  Navigator nav{NavigatorConfig{}};
  NavGoal goal;
  goal.goal_id = 1;
  goal.max_speed = 1.0;
  goal.waypoints = {{3.0, 0.0, 0.0},
                    {3.0, 2.0, deg_to_rad(90)},
                    {1.0, 3.0, deg_to_rad(180)},
                    {-1.0, 1.0, deg_to_rad(-45)},
                    {0.5, -1.5, deg_to_rad(30)},
                    {0.0, 0.0, 0.0}};
  nav.set_goal(goal, 0);

  std::vector<ReachedError> reached;
  double peak_speed = 0.0;
  int64_t now = 0;
  const int64_t limit = 120'000'000;
  while (nav.status().state == NavState::kDriving && now < limit) {
    plant.advance_to(now);
    nav.set_pose(plant.map_T_robot(), now, PoseQuality::kGood);
    const int before = nav.status().waypoints_reached;
    const BodyTwist cmd = nav.update(now);
    if (nav.status().waypoints_reached > before) {
      const Waypoint& w = goal.waypoints[static_cast<size_t>(before)];
      const Pose2& p = plant.map_T_robot();
      reached.push_back({std::hypot(w.x - p.x, w.y - p.y), std::abs(angle_diff(w.theta, p.theta))});
    }
    plant.command(cmd, now);
    peak_speed = std::max(peak_speed, std::hypot(plant.body_twist().vx, plant.body_twist().vy));
    now += 20'000;
  }
  ASSERT_EQ(nav.status().state, NavState::kArrived)
      << to_string(nav.status().state) << " after " << now * 1e-6 << " s";
  ASSERT_EQ(reached.size(), 6u);
  for (size_t i = 0; i < reached.size(); ++i) {
    EXPECT_LE(reached[i].xy, 0.010) << "waypoint " << i;
    EXPECT_LE(reached[i].heading, deg_to_rad(0.5)) << "waypoint " << i;
  }
  // The robot stays where it arrived once commands are zero.
  plant.advance_to(now + 1'000'000);
  EXPECT_LE(std::hypot(plant.map_T_robot().x, plant.map_T_robot().y), 0.010);
  EXPECT_LE(peak_speed, 1.0 + 1e-6);
  EXPECT_GT(peak_speed, 0.95);  // the long legs reach cruise speed
  RecordProperty("mission_time_s", std::to_string(now * 1e-6));
  std::printf("mission time %.2f s, errors:", now * 1e-6);
  for (const auto& r : reached) std::printf(" (%.1f mm, %.3f deg)", r.xy * 1e3, rad_to_deg(r.heading));
  std::printf("\n");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
