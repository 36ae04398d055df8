#include "web_console/console_config.hpp"

#include "common/json_config.hpp"

#include <filesystem>
#include <utility>

namespace refloc {
namespace {

void parse_channels(const JsonConfig& config, ConsoleChannels& c) {
  struct Key {
    const char* name;
    std::string* value;
    const char* meaning;
  };
  const Key keys[] = {
      {"scan", &c.scan, "laser scans drawn (laser_scan_t): points by RSSI, range and RSSI against angle"},
      {"detections", &c.detections, "the extractor's reflectors drawn (reflector_detections_t)"},
      {"clusters", &c.clusters,
       "the extractor's bright clusters, accepted or rejected with the reason, and its energy threshold, "
       "drawn in the sensor view (reflector_clusters_t)"},
      {"matches", &c.matches, "the matcher's associations drawn as lines (reflector_matches_t)"},
      {"pose", &c.pose, "the fused pose drawn with its covariance ellipse and trail (pose2d_t)"},
      {"laser_pose", &c.laser_pose, "the solver's laser fixes drawn with their trail (pose2d_t)"},
      {"ground_truth", &c.ground_truth, "the simulator's true pose drawn with its trail (pose2d_t)"},
      {"nav_goal", &c.nav_goal, "goals drawn (nav_goal_t); the page's goals and stops are published here"},
      {"initial_pose", &c.initial_pose,
       "the page's \"the robot is here\" is published here (pose2d_t; reflector_matcher's "
       "initial_pose_channel)"},
      {"nav_status", &c.nav_status, "the navigator's state shown (nav_status_t)"},
      {"heartbeat", &c.heartbeat, "every service's health shown (heartbeat_t)"},
      {"map_health", &c.map_health, "the matcher's map health shown when published (map_health_t)"}};
  for (const Key& key : keys) {
    const std::string pointer = std::string("/channels/") + key.name;
    *key.value = config.string({pointer, "", std::string("LCM channel: ") + key.meaning}, *key.value);
    if (key.value->empty()) config.fail(pointer, "expected a channel name, got \"\"");
  }
}

void parse_model(const JsonConfig& config, ConsoleModelConfig& m) {
  m.scan_rate_hz =
      config.number({"/model/scan_rate_hz", "Hz",
                     "at most this many scans a second to each page (LMS100_SCAN, REFLECTORS and "
                     "REFLECTOR_MATCHES of one scan; the others are skipped, by the scans' own stamps)"},
                    m.scan_rate_hz, 0.1, 100.0);
  m.pose_rate_hz = config.number({"/model/pose_rate_hz", "Hz",
                                  "at most this many frames a second per pose channel (POSE, LASER_POSE, "
                                  "GROUND_TRUTH); trails take every pose"},
                                 m.pose_rate_hz, 0.1, 200.0);
  m.trail_points = static_cast<size_t>(config.integer(
      {"/model/trail_points", "count", "points kept per trail; the oldest go first (a ring buffer)"},
      static_cast<long long>(m.trail_points), 2, 100000));
  m.trail_step_m = config.number({"/model/trail_step_m", "m",
                                  "a pose is added to its trail after it moved this far from the last point"},
                                 m.trail_step_m, 0.0, 10.0);
}

void parse_server(const JsonConfig& config, ConsoleServerConfig& s) {
  s.listen_address = config.string({"/server/listen_address", "",
                                    "IP address the HTTP/WebSocket server listens on; 127.0.0.1 keeps the "
                                    "page on this computer, 0.0.0.0 serves every interface"},
                                   s.listen_address);
  if (s.listen_address.empty()) config.fail("/server/listen_address", "expected an IP address, got \"\"");
  s.port = static_cast<uint16_t>(
      config.integer({"/server/port", "", "TCP port of the page (http://ADDRESS:PORT/)"}, s.port, 1, 65535));
  s.max_clients = static_cast<size_t>(config.integer(
      {"/server/max_clients", "count", "WebSocket clients at once; one more is refused and counted"},
      static_cast<long long>(s.max_clients), 1, 256));
  s.client_queue_frames = static_cast<size_t>(config.integer(
      {"/server/client_queue_frames", "count",
       "frames waiting for one client; a new frame beyond it is dropped for that client and counted"},
      static_cast<long long>(s.client_queue_frames), 32, 100000));
  s.stalled_client_timeout_s =
      config.number({"/server/stalled_client_timeout_s", "s",
                     "a client that has not taken a frame for this long (stopped reading) is disconnected"},
                    s.stalled_client_timeout_s, 0.1, 600.0);
  s.max_message_bytes = static_cast<size_t>(config.integer(
      {"/server/max_message_bytes", "bytes", "a WebSocket message from a client larger than this is refused"},
      static_cast<long long>(s.max_message_bytes), 64, 1 << 20));
  s.command_inbox = static_cast<size_t>(
      config.integer({"/server/command_inbox", "count",
                      "client commands waiting for the LCM loop; one more is refused and counted"},
                     static_cast<long long>(s.command_inbox), 1, 10000));
  const std::string origins_key = "/server/allowed_origins";
  const size_t n = config.array_size({origins_key, "",
                                      "Origins (\"http://host:port\") whose pages may open the WebSocket "
                                      "besides the page's own (Origin equal to the Host header)"},
                                     false);
  for (size_t i = 0; i < n; ++i) {
    const std::string pointer = origins_key + "/" + std::to_string(i);
    const std::string origin = config.string(pointer, "");
    if (origin.rfind("http://", 0) != 0 && origin.rfind("https://", 0) != 0)
      config.fail(pointer, "expected an origin \"http://host:port\", got \"" + origin + "\"");
    s.allowed_origins.push_back(origin);
  }
}

}  // namespace

WebConsoleConfig parse_web_console_config(const JsonConfig& config, const std::string& base_dir) {
  WebConsoleConfig c;
  parse_channels(config, c.channels);
  parse_model(config, c.model);
  parse_server(config, c.server);
  c.control.enabled = config.boolean(
      {"/control/enabled", "", "the page may send goals and stop (NAV_GOAL); false: it only shows"},
      c.control.enabled);
  c.control.token =
      config.string({"/control/token", "",
                     "secret the page must send with every command (typed in the page); required, at least 8 "
                     "characters, when control is enabled"},
                    c.control.token);
  c.control.initial_pose_sigma_m = config.number(
      {"/control/initial_pose_sigma_m", "m",
       "position std dev published with the page's initial pose (the matcher searches about it)"},
      c.control.initial_pose_sigma_m, 0.01, 5.0);
  c.control.initial_pose_sigma_rad =
      config.number({"/control/initial_pose_sigma_deg", "deg",
                     "heading std dev published with the page's initial pose"},
                    c.control.initial_pose_sigma_rad * 180.0 / M_PI, 0.1, 90.0) *
      M_PI / 180.0;
  if (c.control.enabled && c.control.token.size() < 8)
    config.fail("/control/token", "control is enabled: expected a token of at least 8 characters");
  const std::string map_name = config.string(
      {"/map_file", "",
       "the reflector map shown (keep it the matcher's map_file); a relative path is read from this config "
       "file's folder"},
      "map_demo.json");
  std::filesystem::path map_path(map_name);
  if (map_path.is_relative() && !base_dir.empty()) map_path = std::filesystem::path(base_dir) / map_path;
  c.map_file = map_path.lexically_normal().string();
  c.www_dir = config.string(
      {"/www_dir", "",
       "folder of the page (index.html, *.js, *.css); \"\" = the shipped services/web_console/www"},
      c.www_dir);
  return c;
}

WebConsoleConfig load_web_console_config(const std::string& path, const std::string& default_dir) {
  if (path.empty())
    return parse_web_console_config(JsonConfig(nlohmann::json::object(), "defaults"), default_dir);
  const JsonConfig file = JsonConfig::load_file(path);
  WebConsoleConfig config =
      parse_web_console_config(file, std::filesystem::path(path).parent_path().string());
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
