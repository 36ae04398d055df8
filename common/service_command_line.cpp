#include "common/service_command_line.hpp"

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "common/service_runtime.hpp"

#include "common/config_reference.hpp"
#include "common/robot_config.hpp"

#include <iostream>
#include <utility>

namespace refloc {

ServiceCommandLine::ServiceCommandLine(std::string service_name, const std::string& description,
                                       std::string default_config)
    : app(description), config_path(shipped_path(default_config)), service_name_(std::move(service_name)) {
  add_version_flag(app, service_name_);
  app.add_option("--lcm-url", lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm with ttl=0)");
  app.add_option("--config", config_path, "service config file (JSON); empty for built-in defaults")
      ->capture_default_str();
  app.add_flag("-v,--verbose", verbose, "debug log lines");
  app.add_flag("--print-config", print_config_,
               "print the effective config (every key: value, unit, range, default, meaning) as a commented "
               "JSON file that is valid input, and exit; with --config \"\" the built-in defaults");
  app.add_option("--print-config-format", print_format_, "jsonc (a config file) or markdown (a table)")
      ->check(CLI::IsMember({"jsonc", "markdown"}))
      ->capture_default_str();
}

void ServiceCommandLine::set_config_reader(std::function<void(const JsonConfig&)> reader) {
  config_reader_ = std::move(reader);
}

int ServiceCommandLine::print_config(bool robot) const {
  const std::string& path = robot ? robot_path : config_path;
  const JsonConfig file = path.empty() ? JsonConfig(nlohmann::json::object(), "(built-in defaults)")
                                       : JsonConfig::load_file(path);
  if (robot) {
    parse_robot_config(file);
  } else if (config_reader_) {
    config_reader_(file);
  } else {
    throw std::logic_error(service_name_ + " has no config reader for --print-config");
  }
  file.reject_unknown_keys();
  if (print_format_ == "markdown") {
    std::cout << config_reference_markdown(file.key_records());
  } else {
    std::cout << annotated_config_text(
        file.key_records(), service_name_ + (robot ? " robot file" : " config") + " (" + refloc_version() +
                                ")\nread from " + (path.empty() ? "(built-in defaults)" : path));
  }
  return 0;
}

void ServiceCommandLine::add_robot_option(const std::string& help) {
  robot_path = shipped_path("deploy/config/robot.json");
  app.add_flag("--print-robot-config", print_robot_config_,
               "print the robot file's effective keys like --print-config, and exit");
  app.add_option("--robot", robot_path, help)->capture_default_str();
}

int ServiceCommandLine::run(int argc, char** argv, const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitUsageError;
  }
  if (print_config_ || print_robot_config_)
    return guarded_main(service_name_, [&] { return print_config(print_robot_config_); });
  return guarded_main(service_name_, [&] {
    setup_logging(service_name_, verbose);
    return body();
  });
}

}  // namespace refloc
