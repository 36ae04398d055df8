#pragma once
// The standalone emulator's setup: its config file (the device keys of
// emulator_config_loader.hpp plus world_file, map_T_laser and render) with the command
// line's overrides on top, validated once, and the scan source it implies.

#include "common/se2.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/scan_source.hpp"
#include "world_renderer/scan_renderer.hpp"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

/// Command-line values; the "unset" value of each (empty, -1, 0, false) keeps the file's.
struct EmulatorOverrides {
  std::string bind_address;
  int port = -1;
  std::string protocol;       ///< "" (the file's), cola_a or cola_b
  double frequency_hz = 0;    ///< 25 or 50 [Hz]
  double resolution_deg = 0;  ///< 0.25 or 0.5 [deg]
  double spin_up_s = -1;      ///< [s]
  std::string world_path;     ///< beats the file's world_file
  std::string pose;           ///< "x,y,theta" [m, m, rad], beats the file's map_T_laser
  std::string split;          ///< none|random|boundaries
  int merge = 0;
  int junk = -1;
  bool duplicate_replies = false;
  bool refuse_readiness = false;
  bool refuse_first_write = false;
  int startup_status_scans = -1;
};

struct StandaloneSetup {
  Lms100EmulatorConfig emulator;
  std::string world_path;  ///< empty: the built-in test pattern
  Pose2 map_T_laser;       ///< static sensor pose in the world
  sim::ScanRenderConfig render;
};

/// "x,y,theta" [m, m, rad]; throws ConfigError naming `what` otherwise.
Pose2 parse_pose_text(const std::string& text, const std::string& what);

/// What the standalone emulator's config file holds: the emulator keys, world_file, map_T_laser
/// and render {...}; every key is read (so --print-config lists them), none is interpreted.
struct StandaloneFileKeys {
  Lms100EmulatorConfig emulator;
  std::string world_file;   ///< relative to the file; "" = none
  std::string map_T_laser;  ///< "x,y,theta"; "" = none
  sim::ScanRenderConfig render;
};
StandaloneFileKeys read_standalone_config(const JsonConfig& file);

/// Reads config_path (none when empty; world_file relative to it), applies the overrides
/// and checks the combination; throws ConfigError with the file and key or the option.
StandaloneSetup build_standalone_setup(const std::string& config_path, const EmulatorOverrides& overrides);

/// The world rendered from the static pose, or the test pattern when there is no world.
ScanSource make_standalone_scan_source(const StandaloneSetup& setup);
/// One log line saying what the scan source shows.
std::string describe_scan_source(const StandaloneSetup& setup);
/// One log line saying where the device listens and how it scans.
std::string describe_device(const StandaloneSetup& setup, uint16_t port);

/// The standalone emulator's HEARTBEAT counters by name, in a fixed order.
std::vector<std::pair<const char*, int64_t>> heartbeat_counters(const Lms100EmulatorStats& stats);

}  // namespace refloc
