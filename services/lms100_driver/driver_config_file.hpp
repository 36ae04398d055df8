#pragma once
// deploy/config/lms100_driver.json → the session config and the service's own settings.

#include <string>

#include "common/json_config.hpp"
#include "lms100_driver/lms100_session.hpp"

namespace refloc {

struct DriverServiceConfig {
  Lms100SessionConfig session;
  std::string output_channel = "LMS100_SCAN";
  double error_after_s = 5.0;  ///< without scans for this long the heartbeat says ERROR, before DEGRADED [s]
};

/// Reads every key (all optional, range-checked); throws ConfigError naming file and key.
/// The command line's --host and --port override /host and /port.
DriverServiceConfig parse_driver_config(const JsonConfig& file);
/// The file at path, every key checked and unknown keys refused; the defaults when path is empty.
DriverServiceConfig load_driver_config_file(const std::string& path);

}  // namespace refloc
