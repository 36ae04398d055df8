// refloc-logger-watch: runs lcm-logger as its child and publishes the HEARTBEAT
// lcm-logger does not: service "lcm_logger", ERROR with the reason when the disk is
// (almost) full, the logger keeps exiting, or the bus is busy and the log does not
// grow. Restarts the logger itself (with a growing delay). What the state is, is
// LoggerHealth's; this file wires the child, the probes and the runtime together.

#include "child_process.hpp"
#include "logger_health.hpp"

#include "common/clock.hpp"
#include "common/guarded_main.hpp"
#include "common/json_config.hpp"
#include "common/program_version.hpp"
#include "common/service_runtime.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace refloc {
namespace {

double monotonic_s() { return static_cast<double>(monotonic_us()) * 1e-6; }

void count_message(const lcm::ReceiveBuffer*, const std::string&, int64_t* count) { ++*count; }

struct Options {
  std::string lcm_url;
  std::string log_file;
  double min_free_mb = 100.0;
  LoggerWatchConfig health;
  std::vector<std::string> logger_command;
};

int run(Options o) {
  if (o.logger_command.empty()) throw ConfigError("no logger command after --");
  o.health.min_free_bytes = static_cast<int64_t>(o.min_free_mb * 1024 * 1024);
  const auto slash = o.log_file.rfind('/');
  o.health.log_dir_label = slash == std::string::npos ? "./" : o.log_file.substr(0, slash + 1);
  ServiceRuntime runtime("lcm_logger", o.lcm_url);
  int64_t bus_messages = 0;
  runtime.lcm().subscribeFunction(".*", &count_message, &bus_messages);
  ChildProcess logger(o.logger_command);
  LoggerHealth health(o.health);
  runtime.add_periodic(0.2, [&] {
    logger.keep_running(monotonic_s());
    runtime.counter("logger_exits") = logger.exits();
  });
  runtime.add_periodic(1.0, [&] {
    LoggerObservation seen;
    seen.now_s = monotonic_s();
    seen.logger_running = logger.running();
    seen.last_exit = logger.last_exit();
    seen.bus_messages = bus_messages;
    probe_log_file(o.log_file, seen);
    const LoggerVerdict verdict = health.evaluate(seen);
    runtime.set_state(verdict.state, verdict.detail);
  });
  logger.keep_running(monotonic_s());
  const int rc = runtime.run();
  logger.stop();
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  CLI::App app{"Run lcm-logger and publish its health as HEARTBEAT service lcm_logger"};
  refloc::add_version_flag(app, "refloc-logger-watch");
  refloc::Options o;
  app.add_option("--lcm-url", o.lcm_url, "LCM URL (default: $LCM_DEFAULT_URL or udpm ttl=0)");
  app.add_option("--log-file", o.log_file, "the file the logger writes (with --rotate: PREFIX.0)")
      ->required();
  app.add_option("--min-free-mb", o.min_free_mb,
                 "ERROR below this much free space in the log's directory [MB]")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  app.add_option("--stall-s", o.health.stall_s,
                 "ERROR when the bus is busy and the log unchanged this long [s]")
      ->check(CLI::Range(1.0, 3600.0))
      ->capture_default_str();
  app.add_option("command", o.logger_command, "the logger and its arguments, after --")->required();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-logger-watch", [&] {
    refloc::setup_logging("lcm_logger");
    return refloc::run(o);
  });
}
