// lms100_emulator: a SICK LMS100 on TCP (CoLa-A, port 2111) for tests and demos.
// It renders a world from a static sensor pose (--world, --pose) or, without a
// world, a fixed test pattern. Faults can be set at start (flags, config) and at
// runtime with one-line commands on stdin (--control-stdin; see fault_command.hpp).
// With LCM available it publishes a HEARTBEAT with the emulator's counters.

#include <poll.h>
#include <signal.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <refloc/heartbeat_t.hpp>

#include <atomic>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <thread>

#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/service_runtime.hpp"
#include "lms100_emulator/emulator_config_loader.hpp"
#include "lms100_emulator/fault_command.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/scan_render_source.hpp"
#include "lms100_emulator/test_pattern_scan_source.hpp"
#include "world_renderer/world_loader.hpp"

namespace refloc {
namespace {

struct Options {
  std::string config_path;
  std::string bind_address;
  int port = -1;
  double frequency_hz = 0;
  double resolution_deg = 0;
  double spin_up_s = -1;
  std::string world_path;
  std::string pose;  ///< "x,y,theta" [m, m, rad]
  std::string split;
  int merge = 0;
  int junk = -1;
  bool duplicate_replies = false;
  bool refuse_readiness = false;
  bool refuse_first_write = false;
  int startup_status_scans = -1;
  bool control_stdin = false;
  bool no_lcm = false;
  std::string lcm_url;
  bool verbose = false;
};

Pose2 parse_pose(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  Pose2 pose;
  char comma1 = 0, comma2 = 0;
  if (!(in >> pose.x >> comma1 >> pose.y >> comma2 >> pose.theta) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof()) {
    throw ConfigError(what + ": expected x,y,theta [m, m, rad], got '" + text + "'");
  }
  return pose;
}

/// Applies fault commands typed on stdin until stop is set or stdin ends.
void control_from_stdin(FaultInjector& faults, const std::atomic<bool>& stop) {
  std::string pending;
  while (!stop.load()) {
    pollfd p{STDIN_FILENO, POLLIN, 0};
    if (::poll(&p, 1, 200) <= 0) continue;
    char buffer[256];
    const ssize_t n = ::read(STDIN_FILENO, buffer, sizeof(buffer));
    if (n <= 0) return;
    pending.append(buffer, static_cast<size_t>(n));
    for (size_t eol; (eol = pending.find('\n')) != std::string::npos; pending.erase(0, eol + 1)) {
      const std::string line = pending.substr(0, eol);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      std::string message;
      if (apply_fault_command(line, faults, message)) {
        spdlog::info("{}", message);
      } else {
        spdlog::warn("{}", message);
      }
    }
  }
}

int run(const Options& o) {
  Lms100EmulatorConfig config;
  std::string world_path = o.world_path;
  std::string pose_text = o.pose;
  sim::ScanRenderConfig render_config;
  if (!o.config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(o.config_path);
    config = parse_emulator_config(file);
    const std::string world_in_file = file.string("/world_file", "");
    if (world_path.empty() && !world_in_file.empty()) {
      world_path = (std::filesystem::path(o.config_path).parent_path() / world_in_file).string();
    }
    if (pose_text.empty()) pose_text = file.string("/map_T_laser", "");
    if (file.has("/render")) render_config = sim::parse_scan_render_config(file, "/render");
    file.reject_unknown_keys();
  }
  if (!o.bind_address.empty()) config.bind_address = o.bind_address;
  if (o.port >= 0) config.port = static_cast<uint16_t>(o.port);
  if (o.frequency_hz > 0)
    config.device.scan_frequency_1e2hz = static_cast<uint32_t>(o.frequency_hz * 100.0 + 0.5);
  if (o.resolution_deg > 0)
    config.device.angular_resolution_1e4deg = static_cast<uint32_t>(o.resolution_deg * 1e4 + 0.5);
  const uint32_t f = config.device.scan_frequency_1e2hz, r = config.device.angular_resolution_1e4deg;
  if ((f != 2500 && f != 5000) || (r != 2500 && r != 5000) || (f == 5000 && r == 2500)) {
    throw ConfigError(
        "--frequency/--resolution: an LMS100 scans at 25 Hz (0.25 or 0.5 deg) or 50 Hz (0.5 deg)");
  }
  if (o.spin_up_s >= 0) config.device.spin_up_s = o.spin_up_s;
  if (!o.split.empty()) config.faults.split_mode = parse_split_mode(o.split);
  if (o.merge > 0) config.faults.merge_scan_telegrams = o.merge;
  if (o.junk >= 0) config.faults.junk_bytes_between_telegrams = o.junk;
  config.faults.duplicate_replies |= o.duplicate_replies;
  config.faults.refuse_readiness |= o.refuse_readiness;
  config.refuse_first_write_after_power_up |= o.refuse_first_write;
  if (o.startup_status_scans >= 0) config.startup_status_scans = o.startup_status_scans;

  ScanSource source = make_test_pattern_scan_source();
  if (!world_path.empty()) {
    const Pose2 map_T_laser = parse_pose(pose_text.empty() ? "0,0,0" : pose_text, "--pose");
    auto world = std::make_shared<const sim::World>(sim::load_world(world_path));
    source = sim::make_rendered_scan_source(
        world, [map_T_laser](int64_t) { return map_T_laser; }, render_config, config.random_seed);
    spdlog::info("rendering {} from map_T_laser ({:.3f}, {:.3f}, {:.4f})", world_path, map_T_laser.x,
                 map_T_laser.y, map_T_laser.theta);
  } else if (!pose_text.empty()) {
    throw ConfigError("--pose needs --world (or world_file in the config)");
  } else {
    spdlog::info("no world given: sending the built-in test pattern");
  }

  // Without LCM the process waits for SIGINT/SIGTERM itself; block them before any thread starts.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  if (o.no_lcm) pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  ::signal(SIGPIPE, SIG_IGN);

  std::unique_ptr<ServiceRuntime> runtime;
  if (!o.no_lcm) runtime = std::make_unique<ServiceRuntime>("lms100_emulator", o.lcm_url);

  Lms100Emulator emulator(config, std::move(source));
  emulator.start();
  spdlog::info("LMS100 emulator on {}:{} ({} Hz, {} deg, spin-up {} s)", config.bind_address, emulator.port(),
               config.device.scan_frequency_1e2hz / 100.0, config.device.angular_resolution_1e4deg / 1e4,
               config.device.spin_up_s);

  std::atomic<bool> stop_control{false};
  std::thread control;
  if (o.control_stdin) control = std::thread([&] { control_from_stdin(emulator.faults(), stop_control); });

  int rc = 0;
  if (runtime) {
    runtime->add_periodic(0.5, [&] {
      const Lms100EmulatorStats s = emulator.stats();
      runtime->counter("clients_accepted") = static_cast<int64_t>(s.clients_accepted);
      runtime->counter("requests") = static_cast<int64_t>(s.requests);
      runtime->counter("scan_telegrams_sent") = static_cast<int64_t>(s.scan_telegrams_sent);
      runtime->counter("scans_dropped") = static_cast<int64_t>(s.scans_dropped);
      runtime->counter("disconnects") = static_cast<int64_t>(s.disconnects);
      runtime->set_state(heartbeat_t::STATE_OK, fmt::format("port {}", emulator.port()));
    });
    rc = runtime->run();
  } else {
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
  }
  stop_control = true;
  if (control.joinable()) control.join();
  emulator.stop();
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"SICK LMS100 emulator: CoLa-A over TCP, test pattern or rendered world, fault injection"};
  refloc::Options o;
  app.add_option("--config", o.config_path,
                 "emulator config (JSON; keys in emulator_config_loader.hpp, plus "
                 "world_file, map_T_laser \"x,y,theta\", render {...})");
  app.add_option("--bind", o.bind_address, "address to listen on (default 127.0.0.1)");
  app.add_option("--port", o.port, "TCP port (default 2111; 0 = any free port)")->check(CLI::Range(0, 65535));
  app.add_option("--frequency", o.frequency_hz, "scan frequency [Hz]: 25 or 50 (default 50)");
  app.add_option("--resolution", o.resolution_deg, "angular resolution [deg]: 0.25 or 0.5 (default 0.5)");
  app.add_option("--spin-up-s", o.spin_up_s, "start of measurement to STlms 7 [s] (default 0.2; real ~30)")
      ->check(CLI::Range(0.0, 120.0));
  app.add_option("--world", o.world_path, "world file to render (e.g. deploy/config/world_demo.json)");
  app.add_option("--pose", o.pose, "static sensor pose map_T_laser as x,y,theta [m,m,rad]");
  app.add_option("--split", o.split, "fault: split writes none|random|boundaries");
  app.add_option("--merge", o.merge, "fault: this many scan telegrams per write")->check(CLI::Range(1, 50));
  app.add_option("--junk", o.junk, "fault: junk bytes before every telegram")->check(CLI::Range(0, 10000));
  app.add_flag("--duplicate-replies", o.duplicate_replies, "fault: send every command reply twice");
  app.add_flag("--refuse-readiness", o.refuse_readiness, "fault: STlms never reaches 7");
  app.add_flag("--refuse-first-write", o.refuse_first_write, "fault: sFA 4 on the first sWN after power-up");
  app.add_option("--startup-status-scans", o.startup_status_scans,
                 "stream telegrams with device status 1 0 after sEN");
  app.add_flag("--control-stdin", o.control_stdin,
               "read fault commands from stdin (drop N, stall MS, close, ...)");
  app.add_flag("--no-lcm", o.no_lcm, "no HEARTBEAT (no LCM needed)");
  app.add_option("--lcm-url", o.lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_flag("-v,--verbose", o.verbose, "debug log lines");
  CLI11_PARSE(app, argc, argv);
  return refloc::guarded_main("lms100_emulator", [&] {
    refloc::setup_logging("lms100_emulator", o.verbose);
    return refloc::run(o);
  });
}
