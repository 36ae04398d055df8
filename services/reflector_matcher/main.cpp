// reflector_matcher: REFLECTORS (reflector_detections_t) + POSE prior (pose2d_t)
// -> REFLECTOR_MATCHES (reflector_matches_t), one output per scan.

#include "reflector_matcher/matcher_config_file.hpp"
#include "reflector_matcher/reflector_matcher.hpp"
#include "reflector_matcher/startup_relocalization.hpp"

#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"

#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>

namespace refloc {
namespace {

/// map_T_laser prior (with covariance) from a fused map_T_robot.
PosePrior prior_from_robot_pose(const pose2d_t& pose, const Pose2& robot_T_laser) {
  const Pose2 map_T_robot{pose.x, pose.y, pose.theta};
  Eigen::Matrix3d robot_cov = covariance_from_lcm(pose.covariance);
  if (!robot_cov.allFinite()) robot_cov.setZero();  // the matcher's floors take over
  // d(map_T_laser)/d(map_T_robot): the mount lever arm turns heading error into position error.
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 2) = -s * robot_T_laser.x - c * robot_T_laser.y;
  j(1, 2) = c * robot_T_laser.x - s * robot_T_laser.y;
  return PosePrior{map_T_robot * robot_T_laser, j * robot_cov * j.transpose()};
}

int8_t to_message_status(MatchStatus s) {
  switch (s) {
    case MatchStatus::kOk:
      return reflector_matches_t::STATUS_OK;
    case MatchStatus::kAmbiguous:
      return reflector_matches_t::STATUS_AMBIGUOUS;
    case MatchStatus::kLost:
      break;
  }
  return reflector_matches_t::STATUS_LOST;
}

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path,
        const std::string& map_override) {
  MatcherServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_matcher_service_config(file, std::filesystem::path(config_path).parent_path().string());
    file.reject_unknown_keys();
  } else {
    config =
        parse_matcher_service_config(JsonConfig(nlohmann::json::object(), "(defaults)"), "deploy/config");
  }
  if (!map_override.empty()) config.map_file = map_override;
  const Pose2 robot_T_laser = load_robot_config(robot_path).robot_T_laser;
  ReflectorMatcher matcher(load_reflector_map(config.map_file), config.matcher);
  spdlog::info("map {}: {} reflectors, {} triangles indexed, mode {}", config.map_file,
               matcher.map().reflectors.size(), matcher.indexed_triangles(),
               config.matcher.mode == MatcherMode::kPaper ? "paper" : "default");

  ServiceRuntime runtime("reflector_matcher", lcm_url);
  std::optional<pose2d_t> last_pose;
  std::optional<std::pair<int64_t, Pose2>> last_own_ok;  // scan utime, map_T_laser
  std::vector<ReflectorDetection> detections;
  MatchResult result;
  reflector_matches_t out;
  const auto max_age_us = static_cast<int64_t>(config.prior_max_age * 1e6);
  StartupRelocalization startup(config.relocalize_on_start);

  runtime.subscribe<pose2d_t>(config.prior_channel, [&](const pose2d_t& msg) { last_pose = msg; });
  runtime.subscribe<reflector_detections_t>(config.input_channel, [&](const reflector_detections_t& msg) {
    detections.clear();
    for (const reflector_t& r : msg.reflectors) detections.push_back(from_lcm(r));
    std::optional<PosePrior> prior;
    const bool was_done = startup.done();
    const bool prior_allowed = startup.prior_allowed(msg.utime);
    if (!prior_allowed) {
      ++runtime.counter("startup_scans_without_prior");
    } else if (last_pose && last_pose->status == pose2d_t::STATUS_OK &&
               std::llabs(msg.utime - last_pose->utime) <= max_age_us) {
      prior = prior_from_robot_pose(*last_pose, robot_T_laser);
    } else if (config.use_own_pose_as_prior && last_own_ok &&
               std::llabs(msg.utime - last_own_ok->first) <= max_age_us) {
      const double sxy2 = config.own_prior_sigma_xy * config.own_prior_sigma_xy;
      const double st2 = config.own_prior_sigma_theta * config.own_prior_sigma_theta;
      prior = PosePrior{last_own_ok->second, Eigen::Vector3d(sxy2, sxy2, st2).asDiagonal()};
    }
    matcher.match(detections, prior ? &*prior : nullptr, result);
    startup.on_result(result.status, result.mode);
    if (!was_done && startup.relocalized())
      spdlog::info("relocalized globally after start; tracking from now on");
    if (!was_done && startup.gave_up()) {
      spdlog::warn("no global relocalization within {:.1f} s of start: tracking from the POSE prior",
                   config.relocalize_on_start);
    }
    if (prior && result.mode == MatchMode::kGlobal) ++runtime.counter("tracking_failures");
    if (result.mode == MatchMode::kGlobal) ++runtime.counter("global_relocalizations");
    if (result.status == MatchStatus::kLost) ++runtime.counter("lost_scans");
    if (result.status == MatchStatus::kAmbiguous) ++runtime.counter("ambiguous_scans");
    if (result.status == MatchStatus::kOk) {
      last_own_ok = std::make_pair(msg.utime, result.map_T_laser);
      runtime.set_state(heartbeat_t::STATE_OK);
    } else {
      runtime.set_state(heartbeat_t::STATE_DEGRADED,
                        result.status == MatchStatus::kLost ? "last scan LOST" : "last scan AMBIGUOUS");
    }

    out.utime = msg.utime;
    out.scan_counter = msg.scan_counter;
    out.status = to_message_status(result.status);
    out.mode = result.mode == MatchMode::kTracking ? reflector_matches_t::MODE_TRACKING
                                                   : reflector_matches_t::MODE_GLOBAL;
    out.hypothesis_score = result.hypothesis_score;
    out.runner_up_score = result.runner_up_score;
    out.hypothesis_x = result.map_T_laser.x;
    out.hypothesis_y = result.map_T_laser.y;
    out.hypothesis_theta = result.map_T_laser.theta;
    out.ndetections = static_cast<int32_t>(msg.reflectors.size());
    out.matches.clear();
    for (const ReflectorMatch& m : result.matches) {
      reflector_match_t mm{};
      mm.detection = msg.reflectors[static_cast<size_t>(m.detection_index)];
      mm.map_id = m.map_id;
      mm.map_x = m.map_p_center.x();
      mm.map_y = m.map_p_center.y();
      mm.map_radius = m.map_radius;
      out.matches.push_back(mm);
    }
    out.nmatches = static_cast<int32_t>(out.matches.size());  // encode trusts the length field
    runtime.publish(config.output_channel, out);
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("reflector_matcher",
                                 "Reflector matcher: REFLECTORS (+ POSE prior) -> REFLECTOR_MATCHES",
                                 "deploy/config/reflector_matcher.json");
  cli.add_robot_option("robot geometry file with /laser_mount (JSON)");
  std::string map_override;
  cli.app.add_option("--map", map_override, "reflector map file, overrides the config's map_file");
  return cli.run(argc, argv,
                 [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path, map_override); });
}
