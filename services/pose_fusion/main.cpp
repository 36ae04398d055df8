// pose_fusion: ODOMETRY (odometry_t) + LASER_POSE (pose2d_t) -> POSE (pose2d_t),
// one output per odometry message. Every decision is FusionNode's.

#include "common/clock.hpp"
#include "common/lcm_conversions.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_fusion/fusion_node.hpp"

#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

namespace refloc {
namespace {

int8_t to_message_status(FusionStatus s) {
  switch (s) {
    case FusionStatus::kInitializing:
      return pose2d_t::STATUS_INITIALIZING;
    case FusionStatus::kOk:
      return pose2d_t::STATUS_OK;
    case FusionStatus::kDegraded:
      return pose2d_t::STATUS_DEGRADED;
    case FusionStatus::kLost:
      return pose2d_t::STATUS_LOST;
  }
  return pose2d_t::STATUS_LOST;
}

OdometrySample from_message(const odometry_t& msg) {
  return {msg.utime, {msg.vx, msg.vy, msg.wz}, {msg.x, msg.y, msg.theta}, msg.distance};
}

LaserFixInput from_message(const pose2d_t& msg) {
  LaserFixInput in;
  in.utime = msg.utime;
  in.map_T_robot = {msg.x, msg.y, msg.theta};
  in.covariance = covariance_from_lcm(msg.covariance);
  in.status = msg.status == pose2d_t::STATUS_OK         ? FixStatus::kOk
              : msg.status == pose2d_t::STATUS_DEGRADED ? FixStatus::kDegraded
                                                        : FixStatus::kNoPose;
  in.reflectors_used = msg.reflectors_used;
  return in;
}

pose2d_t to_message(const FusionOutput& pose) {
  pose2d_t out{};
  out.utime = pose.utime;
  out.x = pose.map_T_robot.x;
  out.y = pose.map_T_robot.y;
  out.theta = pose.map_T_robot.theta;
  covariance_to_lcm(pose.covariance, out.covariance);
  out.status = to_message_status(pose.status);
  out.reflectors_used = pose.reflectors_used;
  out.residual = 0.0;
  return out;
}

int run(const std::string& lcm_url, const std::string& robot_path, const std::string& config_path) {
  const FusionServiceConfig config = load_fusion_service_config(config_path);
  ServiceRuntime runtime("pose_fusion", lcm_url);
  FusionNode node(config, load_robot_config(robot_path).odometry_noise);
  const auto set_state = [&] {
    const FusionHealth health = node.health(monotonic_us());
    runtime.set_state(health.ok ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED, health.detail);
  };
  runtime.subscribe<odometry_t>(config.odometry_channel, [&](const odometry_t& msg) {
    const FusionOutput* pose = node.on_odometry(from_message(msg), monotonic_us(), now_utime());
    report_events(runtime, node.events());
    if (pose != nullptr) runtime.publish(config.output_channel, to_message(*pose));
    set_state();
  });
  runtime.subscribe<pose2d_t>(config.fix_channel, [&](const pose2d_t& msg) {
    const std::optional<FusionOutput> pose = node.on_fix(from_message(msg), monotonic_us(), now_utime());
    if (pose) runtime.publish(config.output_channel, to_message(*pose));
    report_events(runtime, node.events());
  });
  runtime.add_periodic(0.5, set_state);  // health by output: also while nothing is accepted
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "pose_fusion",
      "EKF fusion of wheel odometry and delayed laser pose fixes: ODOMETRY + LASER_POSE -> POSE", "");
  cli.add_robot_option("robot file (JSON): the odometry noise model");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_fusion_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.robot_path, cli.config_path); });
}
