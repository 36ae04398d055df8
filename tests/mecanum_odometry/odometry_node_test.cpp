// OdometryNode: what mecanum_odometry does with each WHEEL_ENCODERS sample (publish
// or not, counters and warnings) and its heartbeat freshness rule.

#include "mecanum_odometry/odometry_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// The host's wall clock when a sample stamped utime arrives (1 ms later).
int64_t host(int64_t utime) { return utime + 1'000; }

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

TEST(OdometryNode, PublishesEverySampleButThoseNotNewerThanTheLast) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  ASSERT_NE(node.on_encoders({1'000'000, {0, 0, 0, 0}}, 1, host(1'000'000)),
            nullptr);  // first sample: published at rest
  EXPECT_TRUE(node.events().empty());
  const OdometryEstimate* moved = node.on_encoders({1'010'000, {100, 100, 100, 100}}, 2, host(1'010'000));
  ASSERT_NE(moved, nullptr);
  EXPECT_GT(moved->odom_T_robot.x, 0.0);
  EXPECT_EQ(moved->utime, 1'010'000);
  EXPECT_EQ(node.on_encoders({1'005'000, {200, 200, 200, 200}}, 3, host(1'005'000)), nullptr);
  EXPECT_EQ(count(node.events(), "rejected_wheel_encoders_stamp_not_increasing"), 1);
}

TEST(OdometryNode, GapAndImplausibleSpeedAreCountedAndWarned) {
  OdometryServiceConfig config;
  config.odometry.max_gap = 0.5;
  OdometryNode node(RobotConfig{}, config);
  node.on_encoders({1, {0, 0, 0, 0}}, 1, host(1));
  ASSERT_NE(node.on_encoders({2'000'000, {10, 10, 10, 10}}, 2, host(2'000'000)), nullptr);
  EXPECT_EQ(count(node.events(), "gap_restarts"), 1);
  EXPECT_EQ(node.events()[0].level, NodeEvent::Level::kWarn);
  EXPECT_NE(node.events()[0].log.find("WHEEL_ENCODERS: gap in encoder samples"), std::string::npos);
  // 16384 ticks in 10 ms = 628 rad/s, above the 100 rad/s plausibility bound.
  ASSERT_NE(node.on_encoders({2'010'000, {16394, 16394, 16394, 16394}}, 3, host(2'010'000)), nullptr);
  EXPECT_EQ(count(node.events(), "implausible_samples"), 1);
  EXPECT_NE(node.events()[0].log.find("wheel speed above 100 rad/s"), std::string::npos);
}

TEST(OdometryNode, WheelsDisagreeingCountAsSlip) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  node.on_encoders({1, {0, 0, 0, 0}}, 1, host(1));
  node.on_encoders({10'000, {100, 100, 100, 100}}, 2, host(10'000));
  EXPECT_EQ(count(node.events(), "slip_samples"), 0);
  // Front-left turns 200 ticks further than the rest in 10 ms: 1.8 m/s of disagreement.
  node.on_encoders({20'000, {400, 200, 200, 200}}, 3, host(20'000));
  EXPECT_EQ(count(node.events(), "slip_samples"), 1);
}

TEST(OdometryNode, HealthyWhileSamplesArriveWithinASecond) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  EXPECT_FALSE(node.health(5'000'000).ok);
  EXPECT_EQ(node.health(5'000'000).detail, "no WHEEL_ENCODERS for 1 s");
  node.on_encoders({1, {0, 0, 0, 0}}, 5'000'000, host(1));
  EXPECT_TRUE(node.health(5'999'999).ok);
  EXPECT_FALSE(node.health(6'000'000).ok);
}

TEST(OdometryNode, SamplesArrivingButNoneAcceptedIsDegradedNamingTheRefusal) {
  OdometryNode node(RobotConfig{}, OdometryServiceConfig{});
  node.on_encoders({1, {0, 0, 0, 0}}, 5'000'000, host(1));
  // Samples keep arriving, each stamped no newer than the last: nothing is published.
  for (int64_t t = 5'100'000; t <= 6'500'000; t += 100'000) node.on_encoders({1, {0, 0, 0, 0}}, t, host(1));
  const OdometryHealth h = node.health(6'500'000);
  EXPECT_FALSE(h.ok);
  EXPECT_EQ(h.detail,
            "WHEEL_ENCODERS received but no ODOMETRY published for 1 s: samples refused, "
            "rejected_wheel_encoders_stamp_not_increasing");
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
