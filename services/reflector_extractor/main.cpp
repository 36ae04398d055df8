// reflector_extractor: LMS100_SCAN (laser_scan_t) -> REFLECTORS (reflector_detections_t),
// one output per scan, each detection motion-compensated to the scan's first beam with
// the latest ODOMETRY twist.

#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/motion_compensation.hpp"

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/reflector_detections_t.hpp>

#include <cstdlib>
#include <optional>
#include <string>

namespace refloc {
namespace {

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path) {
  ExtractorServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_extractor_service_config(file);
    file.reject_unknown_keys();
  }
  Pose2 robot_T_laser;
  if (config.motion_compensation && !robot_path.empty())
    robot_T_laser = load_robot_config(robot_path).robot_T_laser;
  ReflectorExtractor extractor(config.extractor);
  spdlog::info("mode {}, energy threshold {:.0f}, radius {:.3f} m, motion compensation {}",
               config.extractor.mode == ExtractorConfig::Mode::kPaper ? "paper" : "default",
               config.extractor.energy_threshold_8bit, config.extractor.reflector_radius,
               config.motion_compensation ? "on" : "off");

  ServiceRuntime runtime("reflector_extractor", lcm_url);
  std::optional<odometry_t> last_odometry;
  LaserScan scan;
  std::vector<ReflectorDetection> detections;
  reflector_detections_t out;
  const auto max_age_us = static_cast<int64_t>(config.odometry_max_age * 1e6);

  runtime.subscribe<odometry_t>(config.odometry_channel, [&](const odometry_t& msg) { last_odometry = msg; });
  runtime.subscribe<laser_scan_t>(config.input_channel, [&](const laser_scan_t& msg) {
    if (!from_lcm(msg, scan)) {
      ++runtime.counter("inconsistent_scans");
      return;
    }
    detections = extractor.extract(scan);
    if (config.motion_compensation) {
      if (last_odometry && std::llabs(last_odometry->utime - scan.utime) <= max_age_us) {
        compensate_motion(detections, scan.utime,
                          BodyTwist{last_odometry->vx, last_odometry->vy, last_odometry->wz}, robot_T_laser);
      } else {
        ++runtime.counter("scans_without_fresh_odometry");
      }
    }
    const ExtractionStats& stats = extractor.stats();
    runtime.counter("rejected_too_few_beams") += stats.rejected_too_few_beams;
    runtime.counter("rejected_shape") += stats.rejected_too_wide + stats.rejected_too_narrow +
                                         stats.rejected_not_round + stats.rejected_radius +
                                         stats.rejected_fit_failed;
    runtime.counter("rejected_occluded") += stats.rejected_occluded;
    if (detections.empty()) ++runtime.counter("scans_without_reflectors");

    out.utime = scan.utime;
    out.scan_counter = static_cast<int32_t>(scan.scan_counter);
    out.clusters_considered = stats.clusters_considered;
    out.clusters_rejected = stats.rejected();
    out.reflectors.clear();
    for (const ReflectorDetection& d : detections) out.reflectors.push_back(to_lcm(d));
    out.nreflectors = static_cast<int32_t>(out.reflectors.size());  // LCM trusts the length field
    runtime.publish(config.output_channel, out);
  });

  runtime.add_periodic(1.0, [&] {
    if (runtime.messages_in() == 0) {
      runtime.set_state(heartbeat_t::STATE_STARTING, "waiting for " + config.input_channel);
    } else {
      runtime.set_state(heartbeat_t::STATE_OK);
    }
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "reflector_extractor",
      "reflector_extractor: laser scans in, retro-reflector detections out (LCM service)",
      "deploy/config/reflector_extractor.json");
  cli.add_robot_option("robot config with the laser mount (robot_T_laser)");
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path); });
}
