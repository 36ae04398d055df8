// pose_fusion: ODOMETRY (odometry_t) + REFLECTOR_MATCHES (reflector_matches_t) + LASER_POSE
// (pose2d_t) -> POSE (pose2d_t), one output per odometry message. Every decision is FusionNode's.

#include "common/clock.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_fusion/fusion_messages.hpp"
#include "pose_fusion/fusion_node.hpp"

namespace refloc {
namespace {

int run(const std::string& lcm_url, const std::string& robot_path, const std::string& config_path) {
  FusionServiceConfig config = load_fusion_service_config(config_path);
  const RobotConfig robot = load_robot_config(robot_path);
  config.fusion.model.robot_T_laser = robot.robot_T_laser;
  ServiceRuntime runtime("pose_fusion", lcm_url);
  FusionNode node(config, robot.odometry_noise);
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
  MatchesInput matches;
  if (config.measurements == FusionMeasurements::kDetections) {
    runtime.subscribe<reflector_matches_t>(config.matches_channel, [&](const reflector_matches_t& msg) {
      from_message(msg, matches);
      node.on_matches(matches, monotonic_us(), now_utime());
      report_events(runtime, node.events());
    });
  }
  runtime.add_periodic(0.5, [&] {
    node.for_each_gauge([&](const char* name, int64_t value) { runtime.counter(name) = value; });
    set_state();
  });  // health by output: also while nothing is accepted
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "pose_fusion",
      "EKF fusion of wheel odometry with the matched reflector detections of each scan, applied at "
      "their scan's time (or the solver's laser fixes): ODOMETRY + REFLECTOR_MATCHES + LASER_POSE -> POSE",
      "");
  cli.add_robot_option("robot file (JSON): the odometry noise model and the laser mount");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_fusion_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.robot_path, cli.config_path); });
}
