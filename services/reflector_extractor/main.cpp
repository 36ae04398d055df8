// reflector_extractor: LMS100_SCAN (laser_scan_t) -> REFLECTORS (reflector_detections_t),
// one output per scan. What happens to a scan is ExtractorNode's; this file converts.

#include "common/clock.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_messages.hpp"
#include "reflector_extractor/extractor_node.hpp"

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>

#include <string>

namespace refloc {
namespace {

void log_settings(const ExtractorServiceConfig& config) {
  const std::string motion = !config.motion_compensation   ? "off"
                             : config.fix_velocity.enabled ? "on (" + config.odometry_channel + ", else " +
                                                                 config.laser_pose_channel + " fixes)"
                                                           : "on (" + config.odometry_channel + " only)";
  spdlog::info("mode {}, energy threshold {:.0f}, radius {:.3f} m, motion compensation {}",
               config.extractor.mode == ExtractorConfig::Mode::kPaper ? "paper" : "default",
               config.extractor.energy_threshold_8bit, config.extractor.reflector_radius, motion);
}

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path) {
  const ExtractorServiceConfig config = load_extractor_service_config(config_path);
  Pose2 robot_T_laser;
  if (config.motion_compensation && !robot_path.empty())
    robot_T_laser = load_robot_config(robot_path).robot_T_laser;
  ExtractorNode node(config, robot_T_laser);
  log_settings(config);

  ServiceRuntime runtime("reflector_extractor", lcm_url);
  LaserScan scan;
  reflector_detections_t out;
  reflector_clusters_t clusters_out;
  runtime.subscribe<odometry_t>(config.odometry_channel, [&](const odometry_t& msg) {
    report_events(runtime, node.on_odometry(odometry_twist_from_message(msg), now_utime()));
  });
  runtime.subscribe<pose2d_t>(config.laser_pose_channel, [&](const pose2d_t& msg) {
    report_events(runtime, node.on_laser_pose(laser_pose_from_message(msg), now_utime()));
  });
  runtime.subscribe<laser_scan_t>(config.input_channel, [&](const laser_scan_t& msg) {
    scan_from_message(msg, scan);
    const ExtractorOutput& o = node.on_scan(scan, now_utime());
    report_events(runtime, o.events);
    if (!o.accepted) return;
    o.for_each_counter([&](const char* name, int64_t by) { runtime.counter(name) += by; });
    to_message(o, out);
    runtime.publish(config.output_channel, out);
    if (config.clusters_channel.empty()) return;
    to_message(o, clusters_out);
    runtime.publish(config.clusters_channel, clusters_out);
  });
  runtime.add_periodic(1.0, [&] {
    const ExtractorHealth h = node.health(runtime.messages_in(), now_utime(), config.input_channel);
    constexpr int8_t kState[] = {heartbeat_t::STATE_STARTING, heartbeat_t::STATE_OK,
                                 heartbeat_t::STATE_DEGRADED};  // in ExtractorHealth::State order
    runtime.set_state(kState[static_cast<int>(h.state)], h.detail);
    if (h.rssi_scale_8bit >= 0) runtime.counter("rssi_scale_8bit") = h.rssi_scale_8bit;  // a gauge
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
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_extractor_service_config(f); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path); });
}
