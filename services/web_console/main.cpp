// web_console: the live console in the browser. Subscribes to what it shows, turns it into JSON
// frames (ConsoleModel) for the HTTP/WebSocket server (ConsoleServer, its own thread), and
// publishes the page's accepted commands as NAV_GOAL from the LCM loop.

#include "common/clock.hpp"
#include "common/program_version.hpp"
#include "common/reflector_map.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "web_console/console_config.hpp"
#include "web_console/console_model.hpp"
#include "web_console/console_server.hpp"
#include "web_console/web_console_messages.hpp"

#include <optional>

namespace refloc {
namespace {

/// Every subscribed message becomes at most one frame, handed to the server (never waits).
template <class Message, class ToFrame>
void show(ServiceRuntime& runtime, ConsoleServer& server, const std::string& channel, ToFrame to_frame) {
  runtime.subscribe<Message>(channel, [&server, to_frame](const Message& msg) {
    if (const std::optional<ConsoleFrame> frame = to_frame(msg)) server.send(*frame);
  });
}

void show_all(ServiceRuntime& rt, ConsoleModel& model, ConsoleServer& server, const ConsoleChannels& ch) {
  using F = std::optional<ConsoleFrame>;
  show<laser_scan_t>(rt, server, ch.scan,
                     [&](const laser_scan_t& m) { return model.on_scan(from_message(m)); });
  show<reflector_detections_t>(rt, server, ch.detections, [&](const reflector_detections_t& m) {
    return model.on_detections(from_message(m));
  });
  show<reflector_clusters_t>(rt, server, ch.clusters, [&](const reflector_clusters_t& m) {
    return model.on_clusters(from_message(m));
  });
  show<reflector_matches_t>(rt, server, ch.matches,
                            [&](const reflector_matches_t& m) { return model.on_matches(from_message(m)); });
  const std::pair<const std::string*, PoseSource> poses[] = {{&ch.pose, PoseSource::kPose},
                                                             {&ch.laser_pose, PoseSource::kLaserPose},
                                                             {&ch.ground_truth, PoseSource::kGroundTruth}};
  for (const auto& [channel, source] : poses)
    show<pose2d_t>(rt, server, *channel, [&model, source = source](const pose2d_t& m) {
      return model.on_pose(source, from_message(m));
    });
  show<nav_goal_t>(rt, server, ch.nav_goal,
                   [&](const nav_goal_t& m) { return F(model.on_goal(from_message(m))); });
  show<nav_status_t>(rt, server, ch.nav_status,
                     [&](const nav_status_t& m) { return F(model.on_nav_status(from_message(m))); });
  show<heartbeat_t>(rt, server, ch.heartbeat,
                    [&](const heartbeat_t& m) { return F(model.on_heartbeat(from_message(m))); });
  show<map_health_t>(rt, server, ch.map_health,
                     [&](const map_health_t& m) { return F(model.on_map_health(from_message(m))); });
}

int run(const std::string& lcm_url, const std::string& config_path) {
  const WebConsoleConfig config = load_web_console_config(config_path, shipped_path("deploy/config"));
  const std::string www = config.www_dir.empty() ? shipped_path("services/web_console/www") : config.www_dir;
  ConsoleServer server(config.server, RequestValidator(config.control, config.server.max_message_bytes),
                       load_www_files(www));
  ConsoleModel model(config.model, load_reflector_map(config.map_file), config.control.enabled);
  ServiceRuntime runtime("web_console", lcm_url);
  const std::string url =
      "http://" + config.server.listen_address + ":" + std::to_string(config.server.port) + "/";
  for (const ConsoleFrame& frame : {model.map_frame(), model.console_frame()}) server.send(frame);
  show_all(runtime, model, server, config.channels);
  runtime.add_periodic(0.02, [&] {  // the page's commands, published from the LCM thread
    for (const ConsoleCommand& command : server.take_commands()) {
      if (command.kind == ConsoleCommand::Kind::kInitialPose)
        runtime.publish(config.channels.initial_pose,
                        initial_pose_message(command, now_utime(), config.control.initial_pose_sigma_m,
                                             config.control.initial_pose_sigma_rad));
      else
        runtime.publish(config.channels.nav_goal, to_message(command, now_utime(), now_utime()));
    }
  });
  runtime.add_periodic(1.0, [&] {
    for (const ConsoleFrame& frame : model.trail_frames()) server.send(frame);
    server.send(model.localization_frame(monotonic_us()));
    for (const auto& [name, value] : server.counters()) runtime.counter(name) = value;
    runtime.counter("scans_skipped") = model.scans_skipped();
    const ConsoleState s = model.state(monotonic_us());  // the URL while OK
    runtime.set_state(s.ok ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED, s.ok ? url : s.detail);
  });
  server.start();
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli("web_console",
                                 "Live console in the browser: map, scan, reflectors, pose and health over "
                                 "HTTP/WebSocket; with control enabled, goals and stop as NAV_GOAL",
                                 "deploy/config/web_console.json");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_web_console_config(f, ""); });
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.config_path); });
}
