// mecanum_odometry: WHEEL_ENCODERS (wheel_encoders_t) -> ODOMETRY (odometry_t),
// one output per encoder sample. Every decision is OdometryNode's.

#include "common/clock.hpp"
#include "common/lcm_conversions.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"
#include "mecanum_odometry/odometry_node.hpp"

#include <refloc/odometry_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

namespace refloc {
namespace {

odometry_t to_message(const OdometryEstimate& e) {
  odometry_t msg{};
  msg.utime = e.utime;
  msg.x = e.odom_T_robot.x;
  msg.y = e.odom_T_robot.y;
  msg.theta = e.odom_T_robot.theta;
  msg.vx = e.twist.vx;
  msg.vy = e.twist.vy;
  msg.wz = e.twist.wz;
  covariance_to_lcm(e.covariance, msg.covariance);
  msg.distance = e.distance;
  msg.slip_indicator = e.slip_indicator;
  return msg;
}

int run(const std::string& lcm_url, const std::string& robot_path, const std::string& config_path) {
  const RobotConfig robot = load_robot_config(robot_path);
  const OdometryServiceConfig config = load_odometry_service_config(config_path);
  ServiceRuntime runtime("mecanum_odometry", lcm_url);
  OdometryNode node(robot, config);
  runtime.subscribe<wheel_encoders_t>(config.input_channel, [&](const wheel_encoders_t& msg) {
    const EncoderReading reading{msg.utime, {msg.ticks[0], msg.ticks[1], msg.ticks[2], msg.ticks[3]}};
    const OdometryEstimate* estimate = node.on_encoders(reading, monotonic_us(), now_utime());
    report_events(runtime, node.events());
    if (estimate != nullptr) runtime.publish(config.output_channel, to_message(*estimate));
  });
  runtime.add_periodic(0.5, [&] {
    const OdometryHealth health = node.health(monotonic_us());
    runtime.set_state(health.ok ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED, health.detail);
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("mecanum_odometry", "Mecanum wheel odometry: WHEEL_ENCODERS -> ODOMETRY",
                                 "");
  cli.add_robot_option("robot geometry file (JSON)");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_odometry_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.robot_path, cli.config_path); });
}
