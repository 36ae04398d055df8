// refloc-motor-bridge-example: a minimal motor-controller bridge. CMD_VEL (twist_t) in,
// four wheel speed setpoints to the controller (zero once no command arrived for
// command_timeout_s), the controller's cumulative counts out on WHEEL_ENCODERS
// (wheel_encoders_t) at encoder_rate_hz (config file keys: motor_bridge_config.cpp). The controller here is a
// stub (stub_motor_controller.hpp); docs/real-robot.md says what to replace.

#include "motor_bridge.hpp"
#include "motor_bridge_config.hpp"
#include "stub_motor_controller.hpp"

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <string>

namespace refloc {
namespace {

wheel_encoders_t encoders_message(const EncoderReading& reading) {
  wheel_encoders_t msg{};
  msg.utime = reading.utime;
  for (size_t i = 0; i < 4; ++i) msg.ticks[i] = reading.ticks[i];
  return msg;
}

int run(const ServiceCommandLine& cli, int32_t start_ticks) {
  const RobotConfig robot = load_robot_config(cli.robot_path);
  const MotorBridgeConfig config = load_motor_bridge_config(cli.config_path);
  ServiceRuntime runtime("motor_bridge", cli.lcm_url);
  MotorBridge bridge(robot, config);
  StubMotorController controller(robot.encoder_ticks_per_rev, start_ticks, monotonic_us());

  runtime.subscribe<twist_t>("CMD_VEL", [&](const twist_t& msg) {
    const CommandVerdict verdict = bridge.on_command({msg.vx, msg.vy, msg.wz}, monotonic_us());
    if (verdict == CommandVerdict::kAccepted) return;
    const char* counter = verdict == CommandVerdict::kNonFinite ? "rejected_cmd_vel_nonfinite"
                                                                : "rejected_cmd_vel_out_of_bounds";
    report_events(runtime, {{counter, NodeEvent::Level::kWarn,
                             fmt::format("CMD_VEL ({}, {}, {}) refused, previous command kept: {}", msg.vx,
                                         msg.vy, msg.wz, to_string(verdict))}});
  });
  runtime.add_periodic(1.0 / config.encoder_rate_hz, [&] {
    const int64_t now = monotonic_us();
    const WheelSetpoint setpoint = bridge.setpoint(now);
    controller.set_wheel_speeds(setpoint.speed_rad_s, now);
    const auto reading = bridge.encoder_reading(controller.read_ticks(now), now_utime());
    if (reading) runtime.publish("WHEEL_ENCODERS", encoders_message(*reading));
    runtime.counter("command_timeouts") = bridge.command_timeouts();
    runtime.counter("encoder_stamps_not_increasing") = bridge.stamps_not_increasing();
    runtime.set_state(heartbeat_t::STATE_OK, setpoint.commanded ? "driving" : "stopped: no fresh CMD_VEL");
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "refloc-motor-bridge-example",
      "Example motor-controller bridge: CMD_VEL -> wheel speeds (stub controller), "
      "encoder counts -> WHEEL_ENCODERS",
      "");
  cli.add_robot_option(
      "robot geometry file (JSON): wheel radius, lx, ly, ticks per revolution, max wheel speed");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_motor_bridge_config(f); });
  int32_t start_ticks = 0;
  cli.app
      .add_option("--start-ticks", start_ticks, "the stub controller's counts at start (they wrap as int32)")
      ->capture_default_str();
  return cli.run(argc, argv, [&] { return refloc::run(cli, start_ticks); });
}
