#pragma once
// web_console's config file (deploy/config/web_console.json). Every key is optional with the
// default written here; --print-config lists each with its unit and meaning.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

class JsonConfig;

/// The LCM channels the console shows and the one it publishes goals on.
struct ConsoleChannels {
  std::string scan = "LMS100_SCAN";
  std::string detections = "REFLECTORS";
  std::string clusters = "REFLECTOR_CLUSTERS";
  std::string matches = "REFLECTOR_MATCHES";
  std::string pose = "POSE";
  std::string laser_pose = "LASER_POSE";
  std::string ground_truth = "GROUND_TRUTH";
  std::string nav_goal = "NAV_GOAL";
  std::string initial_pose = "INITIAL_POSE";
  std::string nav_status = "NAV_STATUS";
  std::string heartbeat = "HEARTBEAT";
  std::string map_health = "MAP_HEALTH";
};

/// What the browser is sent, and how often (ConsoleModel).
struct ConsoleModelConfig {
  double scan_rate_hz = 10.0;  ///< at most this many LMS100_SCAN frames a second to the page [Hz]
  double pose_rate_hz = 20.0;  ///< at most this many frames a second per pose channel [Hz]
  size_t trail_points = 2000;  ///< points kept per trail (POSE, LASER_POSE, GROUND_TRUTH) [count]
  double trail_step_m = 0.02;  ///< a trail point is added after the pose moved this far [m]
};

/// The HTTP/WebSocket server (ConsoleServer).
struct ConsoleServerConfig {
  std::string listen_address = "127.0.0.1";
  uint16_t port = 8080;
  size_t max_clients = 16;                   ///< WebSocket clients at once; more are refused [count]
  size_t client_queue_frames = 64;           ///< frames waiting per client; beyond it dropped [count]
  double stalled_client_timeout_s = 5.0;     ///< a client whose write is pending this long is dropped [s]
  size_t max_message_bytes = 4096;           ///< a client message larger is refused [bytes]
  size_t command_inbox = 16;                 ///< client commands waiting for the LCM loop [count]
  std::vector<std::string> allowed_origins;  ///< Origins accepted besides the page's own host:port
};

/// Whether and how the page may command the robot (RequestValidator).
struct ConsoleControlConfig {
  bool enabled = false;
  std::string token;                                   ///< required (>= 8 characters) when enabled
  double initial_pose_sigma_m = 0.2;                   ///< the page's INITIAL_POSE position std dev [m]
  double initial_pose_sigma_rad = 5.0 * M_PI / 180.0;  ///< its heading std dev [rad]
};

struct WebConsoleConfig {
  ConsoleChannels channels;
  ConsoleModelConfig model;
  ConsoleServerConfig server;
  ConsoleControlConfig control;
  std::string map_file;  ///< the reflector map shown (absolute or relative to the config file)
  std::string www_dir;   ///< the page's folder; "" = the shipped services/web_console/www
};

/// The whole file; base_dir resolves a relative map_file (the config file's folder).
WebConsoleConfig parse_web_console_config(const JsonConfig& config, const std::string& base_dir);

/// Load, parse and reject unknown keys; "" gives the defaults (map_file relative to default_dir).
WebConsoleConfig load_web_console_config(const std::string& path, const std::string& default_dir);

}  // namespace refloc
