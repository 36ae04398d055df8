#include "common/service_command_line.hpp"

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "common/service_runtime.hpp"

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
}

void ServiceCommandLine::add_robot_option(const std::string& help) {
  robot_path = shipped_path("deploy/config/robot.json");
  app.add_option("--robot", robot_path, help)->capture_default_str();
}

int ServiceCommandLine::run(int argc, char** argv, const std::function<int()>& body) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : kExitUsageError;
  }
  return guarded_main(service_name_, [&] {
    setup_logging(service_name_, verbose);
    return body();
  });
}

}  // namespace refloc
