// mecanum_odometry: WHEEL_ENCODERS (wheel_encoders_t) -> ODOMETRY (odometry_t),
// one output per encoder sample.

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "mecanum_odometry/mecanum_odometry.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"

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
  OdometryServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_odometry_service_config(file);
    file.reject_unknown_keys();
  }
  ServiceRuntime runtime("mecanum_odometry", lcm_url);
  MecanumOdometry odometry(robot, config.odometry);
  int64_t last_sample_us = 0;

  runtime.subscribe<wheel_encoders_t>(config.input_channel, [&](const wheel_encoders_t& msg) {
    last_sample_us = monotonic_us();
    const std::array<int32_t, 4> ticks{msg.ticks[0], msg.ticks[1], msg.ticks[2], msg.ticks[3]};
    switch (odometry.add_sample(msg.utime, ticks)) {
      case EncoderSampleResult::kOutOfOrder:
        ++runtime.counter("out_of_order_samples");
        return;
      case EncoderSampleResult::kGapRestart:
        ++runtime.counter("gap_restarts");
        spdlog::warn("{}: gap in encoder samples, integration restarted from the new counts",
                     config.input_channel);
        break;
      case EncoderSampleResult::kImplausible:
        ++runtime.counter("implausible_samples");
        spdlog::warn("{}: wheel speed above {} rad/s, sample skipped", config.input_channel,
                     config.odometry.max_plausible_wheel_speed);
        break;
      case EncoderSampleResult::kFirstSample:
      case EncoderSampleResult::kIntegrated:
        break;
    }
    if (odometry.estimate().slip_indicator > config.slip_warning) ++runtime.counter("slip_samples");
    runtime.publish(config.output_channel, to_message(odometry.estimate()));
  });
  runtime.add_periodic(0.5, [&] {
    const bool fresh = last_sample_us > 0 && monotonic_us() - last_sample_us < 1'000'000;
    if (fresh) {
      runtime.set_state(heartbeat_t::STATE_OK);
    } else {
      runtime.set_state(heartbeat_t::STATE_DEGRADED, "no " + config.input_channel + " for 1 s");
    }
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("mecanum_odometry", "Mecanum wheel odometry: WHEEL_ENCODERS -> ODOMETRY",
                                 "");
  cli.add_robot_option("robot geometry file (JSON)");
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.robot_path, cli.config_path); });
}
