#include "lms100_emulator/standalone_setup.hpp"

#include "common/json_config.hpp"
#include "lms100_emulator/emulator_config_loader.hpp"
#include "lms100_emulator/scan_render_source.hpp"
#include "lms100_emulator/test_pattern_scan_source.hpp"
#include "world_renderer/world_loader.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <memory>
#include <sstream>

namespace refloc {
namespace {

void apply_overrides(const EmulatorOverrides& o, Lms100EmulatorConfig& config) {
  if (!o.bind_address.empty()) config.bind_address = o.bind_address;
  if (!o.protocol.empty()) {
    const bool cola_b = o.protocol == "cola_b";
    // The port follows the protocol's convention (2111 / 2112) unless it was chosen.
    if (cola_b != config.cola_b && config.port == (config.cola_b ? 2112 : 2111))
      config.port = cola_b ? 2112 : 2111;
    config.cola_b = cola_b;
  }
  if (o.port >= 0) config.port = static_cast<uint16_t>(o.port);
  if (o.frequency_hz > 0)
    config.device.scan_frequency_1e2hz = static_cast<uint32_t>(o.frequency_hz * 100.0 + 0.5);
  if (o.resolution_deg > 0)
    config.device.angular_resolution_1e4deg = static_cast<uint32_t>(o.resolution_deg * 1e4 + 0.5);
  if (o.spin_up_s >= 0) config.device.spin_up_s = o.spin_up_s;
  if (!o.split.empty()) config.faults.split_mode = parse_split_mode(o.split);
  if (o.merge > 0) config.faults.merge_scan_telegrams = o.merge;
  if (o.junk >= 0) config.faults.junk_bytes_between_telegrams = o.junk;
  config.faults.duplicate_replies |= o.duplicate_replies;
  config.faults.refuse_readiness |= o.refuse_readiness;
  config.refuse_first_write_after_power_up |= o.refuse_first_write;
  if (o.startup_status_scans >= 0) config.startup_status_scans = o.startup_status_scans;
}

void check_scan_mode(const Lms100DeviceConfig& device) {
  const uint32_t f = device.scan_frequency_1e2hz, r = device.angular_resolution_1e4deg;
  if ((f != 2500 && f != 5000) || (r != 2500 && r != 5000) || (f == 5000 && r == 2500)) {
    throw ConfigError(
        "--frequency/--resolution: an LMS100 scans at 25 Hz (0.25 or 0.5 deg) or 50 Hz (0.5 deg)");
  }
}

}  // namespace

Pose2 parse_pose_text(const std::string& text, const std::string& what) {
  std::istringstream in(text);
  Pose2 pose;
  char comma1 = 0, comma2 = 0;
  if (!(in >> pose.x >> comma1 >> pose.y >> comma2 >> pose.theta) || comma1 != ',' || comma2 != ',' ||
      !(in >> std::ws).eof()) {
    throw ConfigError(what + ": expected x,y,theta [m, m, rad], got '" + text + "'");
  }
  return pose;
}

StandaloneFileKeys read_standalone_config(const JsonConfig& file) {
  StandaloneFileKeys keys;
  keys.emulator = parse_emulator_config(file);
  keys.world_file =
      file.string({"/world_file", "", "world to render, relative to this file; none: test pattern"}, "");
  // Read even when --pose wins, so the key is known to reject_unknown_keys().
  keys.map_T_laser =
      file.string({"/map_T_laser", "", "static sensor pose in the world as \"x,y,theta\" [m, m, rad]"}, "");
  keys.render = sim::parse_scan_render_config(file, "/render");
  return keys;
}

StandaloneSetup build_standalone_setup(const std::string& config_path, const EmulatorOverrides& o) {
  StandaloneSetup setup;
  setup.world_path = o.world_path;
  std::string pose_text = o.pose;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    const StandaloneFileKeys keys = read_standalone_config(file);
    setup.emulator = keys.emulator;
    if (setup.world_path.empty() && !keys.world_file.empty()) {
      setup.world_path = (std::filesystem::path(config_path).parent_path() / keys.world_file).string();
    }
    if (pose_text.empty()) pose_text = keys.map_T_laser;
    setup.render = keys.render;
    file.reject_unknown_keys();
  }
  apply_overrides(o, setup.emulator);
  check_scan_mode(setup.emulator.device);
  if (setup.world_path.empty() && !pose_text.empty())
    throw ConfigError("--pose needs --world (or world_file in the config)");
  if (!setup.world_path.empty())
    setup.map_T_laser = parse_pose_text(pose_text.empty() ? "0,0,0" : pose_text, "--pose");
  return setup;
}

ScanSource make_standalone_scan_source(const StandaloneSetup& setup) {
  if (setup.world_path.empty()) return make_test_pattern_scan_source();
  auto world = std::make_shared<const sim::World>(sim::load_world(setup.world_path));
  const Pose2 map_T_laser = setup.map_T_laser;
  return sim::make_rendered_scan_source(
      world, [map_T_laser](int64_t) { return map_T_laser; }, setup.render, setup.emulator.random_seed);
}

std::string describe_scan_source(const StandaloneSetup& setup) {
  if (setup.world_path.empty()) return "no world given: sending the built-in test pattern";
  const Pose2& p = setup.map_T_laser;
  return fmt::format("rendering {} from map_T_laser ({:.3f}, {:.3f}, {:.4f})", setup.world_path, p.x, p.y,
                     p.theta);
}

std::string describe_device(const StandaloneSetup& setup, uint16_t port) {
  const Lms100DeviceConfig& device = setup.emulator.device;
  return fmt::format("LMS100 emulator on {}:{} ({}, {} Hz, {} deg, spin-up {} s)",
                     setup.emulator.bind_address, port, setup.emulator.cola_b ? "CoLa-B" : "CoLa-A",
                     device.scan_frequency_1e2hz / 100.0, device.angular_resolution_1e4deg / 1e4,
                     device.spin_up_s);
}

std::vector<std::pair<const char*, int64_t>> heartbeat_counters(const Lms100EmulatorStats& s) {
  return {{"clients_accepted", static_cast<int64_t>(s.clients_accepted)},
          {"requests", static_cast<int64_t>(s.requests)},
          {"scan_telegrams_sent", static_cast<int64_t>(s.scan_telegrams_sent)},
          {"scans_dropped", static_cast<int64_t>(s.scans_dropped)},
          {"disconnects", static_cast<int64_t>(s.disconnects)}};
}

}  // namespace refloc
