#pragma once
// The command line every refloc service shares, and how its main() runs:
// --help, --version, --lcm-url, --config FILE, -v; usage errors reported as CLI11 does (exit 64);
// then the body under guarded_main (bad config: one line, exit 2).

#include "common/json_config.hpp"

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace refloc {

class ServiceCommandLine {
 public:
  /// default_config: the service's file under deploy/config ("" = built-in defaults), resolved
  /// against the refloc root (shipped_path), not the working directory.
  ServiceCommandLine(std::string service_name, const std::string& description, std::string default_config);

  /// Adds --robot FILE (default deploy/config/robot.json) for services that need the robot geometry.
  void add_robot_option(const std::string& help);

  /// The function that reads this service's config file (parse_*_config): --print-config runs
  /// it on the --config file, or on {} for the built-in defaults, and prints every key it read.
  void set_config_reader(std::function<void(const JsonConfig&)> reader);

  /// Parses argv, sets up logging and runs body under guarded_main; returns the exit code.
  /// --print-config / --print-robot-config print and return instead of running body.
  int run(int argc, char** argv, const std::function<int()>& body);

  CLI::App app;         ///< for service-specific options
  std::string lcm_url;  ///< empty: $LCM_DEFAULT_URL, else udpm with ttl=0
  std::string config_path;
  std::string robot_path;  ///< default: deploy/config/robot.json under the refloc root
  bool verbose = false;

 private:
  int print_config(bool robot) const;

  std::string service_name_;
  std::function<void(const JsonConfig&)> config_reader_;
  bool print_config_ = false;
  bool print_robot_config_ = false;
  std::string print_format_ = "jsonc";
};

}  // namespace refloc
