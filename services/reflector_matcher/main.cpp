// reflector_matcher: REFLECTORS (+ POSE, INITIAL_POSE, LMS100_SCAN) -> REFLECTOR_MATCHES, MAP_HEALTH.

#include "reflector_matcher/map_health_messages.hpp"
#include "reflector_matcher/matcher_config_file.hpp"
#include "reflector_matcher/matcher_messages.hpp"
#include "reflector_matcher/matcher_node.hpp"

#include "common/clock.hpp"
#include "common/lcm_conversions.hpp"
#include "common/node_event_report.hpp"
#include "common/reflector_map.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"

#include <refloc/laser_scan_t.hpp>
#include <refloc/map_health_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

namespace refloc {
namespace {

void log_startup(StartupEvent event, double window_s) {
  if (event == StartupEvent::kRelocalized)
    spdlog::info("relocalized globally after start; tracking from now on");
  if (event == StartupEvent::kGaveUp)
    spdlog::warn("no global relocalization within {:.1f} s of start: tracking from the POSE prior", window_s);
}
// MAP_HEALTH once a period, its counters in the heartbeat, each state change logged.
void wire_map_health(ServiceRuntime& runtime, MatcherNode& node, const MapHealthConfig& config) {
  MapHealthMonitor* monitor = node.map_health();
  if (monitor == nullptr) return;
  runtime.subscribe<laser_scan_t>(config.scan_channel,
                                  [&node, scan = LaserScan()](const laser_scan_t& msg) mutable {
                                    copy_from_lcm(msg, scan);
                                    node.on_scan(scan);
                                  });
  runtime.add_periodic(
      config.publish_period, [&runtime, monitor, channel = config.channel, out = map_health_t(),
                              changes = std::vector<MapHealthChange>()]() mutable {
        const MapHealthReport& report = monitor->report(now_utime(), monotonic_us(), changes);
        for (const MapHealthChange& c : changes)
          c.warning ? spdlog::warn("map health: {}", c.text) : spdlog::info("map health: {}", c.text);
        report.for_each_counter([&](const char* name, int64_t value) { runtime.counter(name) = value; });
        to_message(report, out);
        runtime.publish(channel, out);
      });
}

int run(const std::string& lcm_url, const std::string& config_path, const std::string& robot_path,
        const std::string& map_override) {
  MatcherServiceConfig config = load_matcher_service_config(config_path);
  if (!map_override.empty()) config.map_file = map_override;
  MatcherNode node(load_reflector_map(config.map_file), config, load_robot_config(robot_path).robot_T_laser);
  spdlog::info("map {}: {} reflectors, {} triangles indexed, mode {}", config.map_file,
               node.matcher().map().reflectors.size(), node.matcher().indexed_triangles(),
               config.matcher.mode == MatcherMode::kPaper ? "paper" : "default");
  for (const std::string& w : node.matcher().map().warnings) spdlog::warn("map {}: {}", config.map_file, w);

  ServiceRuntime runtime("reflector_matcher", lcm_url);
  std::vector<ReflectorDetection> detections;
  reflector_matches_t out;
  runtime.subscribe<pose2d_t>(config.prior_channel, [&](const pose2d_t& msg) {
    report_events(runtime, node.on_pose(fused_pose_from_message(msg), now_utime()));
  });
  runtime.subscribe<pose2d_t>(config.initial_pose_channel, [&](const pose2d_t& msg) {
    report_events(runtime, node.on_initial_pose(fused_pose_from_message(msg)));
  });
  runtime.subscribe<reflector_detections_t>(config.input_channel, [&](const reflector_detections_t& msg) {
    detections_from_message(msg, detections);
    const MatcherOutput& o = node.on_detections(msg.utime, msg.scan_counter, detections, now_utime());
    report_events(runtime, o.events);
    runtime.set_state(o.ok() ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED,
                      o.ok() ? "" : o.degraded_detail());
    if (!o.accepted) return;
    log_startup(o.startup_event, config.prior.relocalize_on_start);
    o.for_each_counter([&](const char* name, int64_t by) { runtime.counter(name) += by; });
    to_message(msg, o.result, out);
    runtime.publish(config.output_channel, out);
  });
  wire_map_health(runtime, node, config.map_health);
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
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_matcher_service_config(f, "."); });
  return cli.run(argc, argv,
                 [&] { return refloc::run(cli.lcm_url, cli.config_path, cli.robot_path, map_override); });
}
