#include "robot_sim/robot_sim_node.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kStart = 1'000'000;

PlantSetup plant_setup() {
  PlantSetup setup;
  setup.initial_map_T_robot = Pose2{2.0, 1.0, 0.0};
  return setup;
}

TEST(RobotSimNode, NonFiniteCommandIsRefusedAndDoesNotMoveTheRobot) {
  RobotSimNode node(RobotConfig{}, plant_setup(), kStart);
  EXPECT_FALSE(node.on_command({std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0}, kStart));
  EXPECT_FALSE(node.on_command({0.0, std::numeric_limits<double>::infinity(), 0.0}, kStart));
  node.advance(kStart + 500'000);
  EXPECT_DOUBLE_EQ(node.plant().map_T_robot().x, 2.0);
  EXPECT_TRUE(node.on_command({0.2, 0.0, 0.0}, kStart + 500'000));
}

TEST(RobotSimNode, AdvanceMovesInWholeStepsOnly) {
  RobotSimNode node(RobotConfig{}, plant_setup(), kStart);
  node.advance(kStart + 10'500);  // 10.5 steps of 1 ms
  EXPECT_EQ(node.plant().utime(), kStart + 10'000);
  EXPECT_EQ(node.ground_truth_tick(kStart + 10'999).utime, kStart + 10'000);
  EXPECT_EQ(node.ground_truth_tick(kStart + 11'000).utime, kStart + 11'000);
}

TEST(RobotSimNode, LaserPoseIsRecordedAtEachStepInTheMapFrame) {
  RobotConfig robot;
  robot.robot_T_laser = Pose2{0.3, 0.0, 0.0};
  RobotSimNode node(robot, plant_setup(), kStart);
  EXPECT_NEAR(node.laser_poses()->at(kStart).x, 2.3, 1e-12);
  for (int64_t t = kStart; t <= kStart + 1'000'000; t += 20'000) {
    node.on_command({0.5, 0.0, 0.0}, t);
    node.advance(t);
  }
  const TruePose truth = node.ground_truth_tick(kStart + 1'000'000);
  EXPECT_GT(truth.map_T_robot.x, 2.3);
  EXPECT_NEAR(node.laser_poses()->at(truth.utime).x, truth.map_T_robot.x + 0.3, 1e-9);
}

TEST(RobotSimNode, RendererAheadOfTheTicksGetsTheSimulatedPoseNotTheLastTicked) {
  // The LCM thread's ticks lag on a loaded host; the beam's pose must still be the
  // pose at the beam's time (it was the last ticked one: 60-150 ms stale in CI).
  RobotConfig robot;
  robot.robot_T_laser = Pose2{0.3, 0.0, 0.0};
  RobotSimNode node(robot, plant_setup(), kStart);
  node.on_command({0.5, 0.0, 0.0}, kStart);
  node.advance(kStart + 200'000);
  const double ticked_x = node.plant().map_T_robot().x;
  const Pose2 beam = node.map_T_laser_at(kStart + 300'000);  // no tick for 100 ms
  EXPECT_EQ(node.plant().utime(), kStart + 300'000);
  EXPECT_NEAR(beam.x, node.plant().map_T_robot().x + 0.3, 1e-9);
  // 100 ms of acceleration-limited motion (22.8 mm): well beyond the last ticked pose.
  EXPECT_GT(beam.x - 0.3 - ticked_x, 0.02);
  EXPECT_EQ(node.laser_poses_outside_history(), 0u);
  // A later tick does not move the plant back or twice.
  EXPECT_EQ(node.ground_truth_tick(kStart + 300'500).utime, kStart + 300'000);
}

TEST(RobotSimNode, BeamTimesTheSimulationCannotReachAreCountedNotSimulated) {
  RobotSimNode node(RobotConfig{}, plant_setup(), kStart);
  node.map_T_laser_at(kStart + RobotSimNode::kMaxRenderLead_us + 1);  // a broken clock
  EXPECT_EQ(node.plant().utime(), kStart);
  node.advance(kStart + 3'000'000);
  node.map_T_laser_at(kStart);  // older than the 2 s kept
  EXPECT_EQ(node.laser_poses_outside_history(), 2u);
}

TEST(RobotSimNode, CommandTimeoutIsReportedOnceWhenTheCommandGoesStale) {
  RobotSimNode node(RobotConfig{}, plant_setup(), kStart);
  EXPECT_FALSE(node.encoder_tick(kStart + 10'000).command_timed_out);  // stale from the start: no edge
  node.on_command({0.3, 0.0, 0.0}, kStart + 10'000);
  EXPECT_FALSE(node.encoder_tick(kStart + 20'000).command_timed_out);
  int timeouts = 0;
  for (int64_t t = kStart + 30'000; t <= kStart + 1'000'000; t += 10'000)
    timeouts += node.encoder_tick(t).command_timed_out ? 1 : 0;
  EXPECT_EQ(timeouts, 1);  // command_timeout 0.2 s passed once, reported once
}

TEST(RobotSimNode, EncoderTicksStartAtTheConfiguredCount) {
  PlantSetup setup = plant_setup();
  setup.encoder_start_ticks = 2'147'000'000;
  RobotSimNode node(RobotConfig{}, setup, kStart);
  const EncoderSample sample = node.encoder_tick(kStart + 5'000);
  EXPECT_EQ(sample.utime, kStart + 5'000);
  for (const int32_t t : sample.ticks) EXPECT_EQ(t, 2'147'000'000);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
