#include "motor_bridge.hpp"
#include "stub_motor_controller.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

RobotConfig robot() { return RobotConfig{}; }  // the deployed robot.json's values are the defaults

TEST(MotorBridge, StopsTheWheelsWhenNoCommandIsFresh) {
  MotorBridge bridge(robot(), {});
  EXPECT_FALSE(bridge.setpoint(0).commanded);
  ASSERT_EQ(bridge.on_command({0.5, 0.0, 0.0}, 1'000'000), CommandVerdict::kAccepted);
  EXPECT_TRUE(bridge.setpoint(1'200'000).commanded);  // 0.2 s old: still fresh
  const WheelSetpoint stale = bridge.setpoint(1'200'001);
  EXPECT_FALSE(stale.commanded);
  for (double w : stale.speed_rad_s) EXPECT_EQ(w, 0.0);
  EXPECT_EQ(bridge.command_timeouts(), 1);
  bridge.setpoint(1'300'000);
  EXPECT_EQ(bridge.command_timeouts(), 1);  // one timeout per command stream that ends
}

TEST(MotorBridge, WheelSpeedsAreTheInverseOfTheOdometrysKinematics) {
  MotorBridge bridge(robot(), {});
  const BodyTwist twist{0.4, -0.2, 0.3};
  bridge.on_command(twist, 0);
  const BodyTwist back = MecanumKinematics(robot()).forward(bridge.setpoint(0).speed_rad_s);
  EXPECT_NEAR(back.vx, twist.vx, 1e-12);
  EXPECT_NEAR(back.vy, twist.vy, 1e-12);
  EXPECT_NEAR(back.wz, twist.wz, 1e-12);
}

TEST(MotorBridge, ScalesAllWheelsTogetherToTheSpeedLimitKeepingTheDirection) {
  MotorBridge bridge(robot(), {});
  bridge.on_command({3.0, 1.0, 0.0}, 0);  // 3 m/s needs 39 rad/s, over 20
  const WheelSetpoint s = bridge.setpoint(0);
  double largest = 0.0;
  for (double w : s.speed_rad_s) largest = std::max(largest, std::abs(w));
  EXPECT_NEAR(largest, robot().max_wheel_speed, 1e-9);
  const BodyTwist back = MecanumKinematics(robot()).forward(s.speed_rad_s);
  EXPECT_NEAR(back.vx / back.vy, 3.0, 1e-9);
}

TEST(MotorBridge, RefusesBrokenCommandsAndKeepsThePreviousOne) {
  MotorBridge bridge(robot(), {});
  bridge.on_command({0.5, 0.0, 0.0}, 0);
  EXPECT_EQ(bridge.on_command({std::numeric_limits<double>::quiet_NaN(), 0, 0}, 10),
            CommandVerdict::kNonFinite);
  EXPECT_EQ(bridge.on_command({1e308, 0, 0}, 20), CommandVerdict::kOutOfBounds);
  EXPECT_NEAR(MecanumKinematics(robot()).forward(bridge.setpoint(30).speed_rad_s).vx, 0.5, 1e-12);
  EXPECT_FALSE(bridge.setpoint(200'001).commanded);  // the kept command ages from its own receipt
}

TEST(MotorBridge, SkipsAnEncoderSampleWhoseStampIsNotAfterThePrevious) {
  MotorBridge bridge(robot(), {});
  ASSERT_TRUE(bridge.encoder_reading({1, 2, 3, 4}, 1000).has_value());
  EXPECT_FALSE(bridge.encoder_reading({1, 2, 3, 4}, 1000).has_value());
  EXPECT_FALSE(bridge.encoder_reading({1, 2, 3, 4}, 999).has_value());
  EXPECT_EQ(bridge.stamps_not_increasing(), 2);
  EXPECT_EQ(bridge.encoder_reading({5, 6, 7, 8}, 1001)->ticks[3], 8);
}

TEST(StubMotorController, CountsTicksAtTheSetSpeedAndWrapsAsInt32) {
  const int ticks_per_rev = 16384;
  StubMotorController controller(ticks_per_rev, 2147483000, 0);
  controller.set_wheel_speeds({2 * M_PI, -2 * M_PI, 0.0, M_PI}, 0);
  const auto ticks = controller.read_ticks(1'000'000);  // one second: one turn, minus one, none, half
  EXPECT_EQ(static_cast<int64_t>(ticks[0]), 2147483000LL + 16384 - 4294967296LL);
  EXPECT_EQ(ticks[1], 2147483000 - 16384);
  EXPECT_EQ(ticks[2], 2147483000);
  EXPECT_EQ(static_cast<int64_t>(ticks[3]), 2147483000LL + 8192 - 4294967296LL);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
