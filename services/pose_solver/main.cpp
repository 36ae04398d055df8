// pose_solver: REFLECTOR_MATCHES (reflector_matches_t) -> LASER_POSE (pose2d_t,
// map_T_robot at the scan's reference time), one output per scan.

#include "pose_solver/pose_solver.hpp"
#include "pose_solver/solver_config_file.hpp"

#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"

#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_matches_t.hpp>

namespace refloc {
namespace {

int8_t to_message_status(SolveStatus s) {
  switch (s) {
    case SolveStatus::kOk:
      return pose2d_t::STATUS_OK;
    case SolveStatus::kDegraded:
      return pose2d_t::STATUS_DEGRADED;
    case SolveStatus::kLost:
      break;
  }
  return pose2d_t::STATUS_LOST;
}

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path) {
  SolverServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_solver_service_config(file);
    file.reject_unknown_keys();
  }
  const Pose2 robot_T_laser = load_robot_config(robot_path).robot_T_laser;
  PoseSolver solver(config.solver, robot_T_laser);
  spdlog::info("mode {}, laser mount ({:.3f} m, {:.3f} m, {:.4f} rad)",
               config.solver.mode == SolverMode::kPaper ? "paper" : "default", robot_T_laser.x,
               robot_T_laser.y, robot_T_laser.theta);

  ServiceRuntime runtime("pose_solver", lcm_url);
  std::vector<ReflectorDetection> detections;
  std::vector<ReflectorMatch> matches;
  PoseSolution solution;
  pose2d_t out{};

  runtime.subscribe<reflector_matches_t>(config.input_channel, [&](const reflector_matches_t& msg) {
    // Each match carries its detection: the solver sees them as detections 0..n-1.
    detections.clear();
    matches.clear();
    for (const reflector_match_t& m : msg.matches) {
      matches.push_back({static_cast<int>(detections.size()), m.map_id, {m.map_x, m.map_y}, m.map_radius});
      detections.push_back(from_lcm(m.detection));
    }
    out.utime = msg.utime;
    if (msg.status == reflector_matches_t::STATUS_OK) {
      solver.solve(detections, matches, solution);
      out.status = to_message_status(solution.status);
    } else {
      // The matcher's doubt wins: a pose from an ambiguous association is not a fix.
      solution.status = SolveStatus::kLost;
      solution.reflectors_used = 0;
      solution.rms_residual = 0.0;
      out.status = msg.status == reflector_matches_t::STATUS_AMBIGUOUS ? pose2d_t::STATUS_AMBIGUOUS
                                                                       : pose2d_t::STATUS_LOST;
    }
    const bool has_pose =
        msg.status == reflector_matches_t::STATUS_OK && solution.status != SolveStatus::kLost;
    out.x = has_pose ? solution.map_T_robot.x : 0.0;
    out.y = has_pose ? solution.map_T_robot.y : 0.0;
    out.theta = has_pose ? solution.map_T_robot.theta : 0.0;
    // No fix: a covariance no consumer mistakes for information.
    covariance_to_lcm(has_pose ? solution.covariance : Eigen::Matrix3d(Eigen::Matrix3d::Identity() * 1e6),
                      out.covariance);
    out.reflectors_used = has_pose ? solution.reflectors_used : 0;
    out.residual = has_pose ? solution.rms_residual : 0.0;
    if (out.status == pose2d_t::STATUS_OK) {
      runtime.set_state(heartbeat_t::STATE_OK);
    } else {
      if (out.status == pose2d_t::STATUS_DEGRADED) ++runtime.counter("degraded_fixes");
      if (out.status == pose2d_t::STATUS_LOST) ++runtime.counter("lost_fixes");
      if (out.status == pose2d_t::STATUS_AMBIGUOUS) ++runtime.counter("ambiguous_fixes");
      runtime.set_state(heartbeat_t::STATE_DEGRADED,
                        has_pose ? "last fix DEGRADED" : "no fix from the last scan");
    }
    if (has_pose && solution.reflectors_used < static_cast<int>(matches.size())) {
      runtime.counter("outlier_matches") += static_cast<int64_t>(matches.size()) - solution.reflectors_used;
    }
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
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path); });
}
