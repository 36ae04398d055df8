// robot_sim facing a hostile or broken commander: NaN/inf and absurd but finite twists
// (1e308 m/s used to turn the true pose into NaN for good). Refused and counted, the
// previous command kept; fast but sane commands are saturated by the wheels; the true
// pose and the encoder counts stay finite and the robot obeys good commands after.

#include "robot_sim/robot_sim_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kStart = 1'000'000;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

bool finite(const Pose2& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.theta); }

TEST(RobotSimHostileInput, NonFiniteOrAbsurdTwistInEveryFieldIsRefusedCountedAndTheRobotStaysFinite) {
  for (int field = 0; field < 3; ++field) {
    for (const double bad : {kNaN, kInf, -kInf, 1e300, -1e308, 1e308}) {
      const std::string what = std::to_string(field) + " = " + std::to_string(bad);
      RobotSimNode node(RobotConfig{}, PlantSetup{}, kStart);
      ASSERT_TRUE(node.on_command({0.3, 0.0, 0.0}, kStart));
      BodyTwist twist{0.3, 0.0, 0.0};
      (field == 0 ? twist.vx : field == 1 ? twist.vy : twist.wz) = bad;
      EXPECT_FALSE(node.on_command(twist, kStart + 10'000)) << what;
      EXPECT_EQ(count(node.events(),
                      std::isfinite(bad) ? "rejected_cmd_vel_out_of_bounds" : "rejected_cmd_vel_nonfinite"),
                1)
          << what;
      EXPECT_EQ(node.events()[0].level, NodeEvent::Level::kWarn);
      for (int64_t t = kStart + 20'000; t <= kStart + 1'000'000; t += 10'000) {
        if (t < kStart + 150'000) node.on_command({0.3, 0.0, 0.0}, t);
        const EncoderSample e = node.encoder_tick(t);
        const TruePose truth = node.ground_truth_tick(t);
        ASSERT_TRUE(finite(truth.map_T_robot)) << what << " at " << t;
        (void)e;
      }
      // The refused command changed nothing: the good one drove it, then it stopped.
      EXPECT_GT(node.plant().map_T_robot().x, 0.02) << what;
      EXPECT_LT(node.plant().map_T_robot().x, 0.35) << what;
      EXPECT_NEAR(node.plant().map_T_robot().y, 0.0, 1e-9) << what;
    }
  }
}

TEST(RobotSimHostileInput, AFastButSaneCommandIsSaturatedByTheWheelsNotRefused) {
  const RobotConfig robot;
  RobotSimNode node(robot, PlantSetup{}, kStart);
  const double reach = robot.max_wheel_speed * robot.wheel_radius;  // 1.52 m/s
  ASSERT_TRUE(node.on_command({5.0 * reach, 0.0, 0.0}, kStart));
  EXPECT_TRUE(node.events().empty());
  for (int64_t t = kStart; t <= kStart + 150'000; t += 10'000) {
    node.on_command({5.0 * reach, 0.0, 0.0}, t);
    node.advance(t);
  }
  for (double w : node.plant().wheel_speeds()) EXPECT_LE(std::abs(w), robot.max_wheel_speed + 1e-9);
  EXPECT_TRUE(finite(node.plant().map_T_robot()));
  EXPECT_FALSE(node.on_command({11.0 * reach, 0.0, 0.0}, kStart + 160'000));  // beyond 10x: absurd
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
