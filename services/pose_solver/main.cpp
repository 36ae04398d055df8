// pose_solver: REFLECTOR_MATCHES (reflector_matches_t) -> LASER_POSE (pose2d_t,
// map_T_robot at the scan's reference time), one output per scan. The fix and its
// status are SolverNode's (make_laser_fix); this file converts.

#include "pose_solver/solver_config_file.hpp"
#include "pose_solver/solver_messages.hpp"
#include "pose_solver/solver_node.hpp"

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"

#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_matches_t.hpp>

namespace refloc {
namespace {

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path) {
  SolverServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_solver_service_config(file);
    file.reject_unknown_keys();
  }
  const Pose2 robot_T_laser = load_robot_config(robot_path).robot_T_laser;
  SolverNode node(config.solver, robot_T_laser);
  spdlog::info("mode {}, laser mount ({:.3f} m, {:.3f} m, {:.4f} rad)",
               config.solver.mode == SolverMode::kPaper ? "paper" : "default", robot_T_laser.x,
               robot_T_laser.y, robot_T_laser.theta);
  const RangeBiasConfig& bias = config.solver.range_bias;
  spdlog::info("range bias {}: prior {:.1f} +- {:.1f} mm, drift {:.2f} mm/sqrt(s)",
               bias.estimate ? "estimated" : "not estimated (its sigma inflates the covariance)",
               1e3 * bias.prior_mean, 1e3 * bias.prior_sigma, 1e3 * bias.drift);

  ServiceRuntime runtime("pose_solver", lcm_url);
  std::vector<ReflectorDetection> detections;
  std::vector<ReflectorMatch> matches;
  pose2d_t out{};
  runtime.subscribe<reflector_matches_t>(config.input_channel, [&](const reflector_matches_t& msg) {
    matches_from_message(msg, detections, matches);
    const SolverOutput& o =
        node.on_message(msg.utime, msg.scan_counter, match_verdict_from_message(msg.status), detections,
                        matches, now_utime());
    report_events(runtime, o.events);
    runtime.set_state(o.ok() ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED,
                      o.ok() ? o.ok_detail() : o.degraded_detail());
    if (!o.accepted) return;
    o.for_each_counter([&](const char* name, int64_t by) { runtime.counter(name) += by; });
    o.for_each_gauge([&](const char* name, int64_t value) { runtime.counter(name) = value; });
    to_message(*o.fix, out);
    runtime.publish(config.output_channel, out);
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("pose_solver",
                                 "Pose solver: REFLECTOR_MATCHES -> LASER_POSE (map_T_robot with covariance)",
                                 "deploy/config/pose_solver.json");
  cli.add_robot_option("robot geometry file with /laser_mount (JSON)");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_solver_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path); });
}
