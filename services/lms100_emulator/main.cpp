// lms100_emulator: a SICK LMS100 on TCP (CoLa-A 2111 or CoLa-B 2112) for tests and demos, rendering a world
// from a pose (--world, --pose) or a test pattern; faults from flags, the config and stdin commands
// (--control-stdin, fault_command.hpp); HEARTBEAT with its counters over LCM.

#include <signal.h>
#include <unistd.h>
#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <refloc/heartbeat_t.hpp>
#include <string>

#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "lms100_emulator/emulator_config_loader.hpp"
#include "lms100_emulator/fault_command.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/standalone_setup.hpp"

namespace refloc {
namespace {

void report_fault_command(bool accepted, const std::string& message) {
  accepted ? spdlog::info("{}", message) : spdlog::warn("{}", message);
}

int run(const std::string& config_path, const EmulatorOverrides& overrides, bool control_stdin, bool no_lcm,
        const std::string& lcm_url) {
  const StandaloneSetup setup = build_standalone_setup(config_path, overrides);
  ScanSource source = make_standalone_scan_source(setup);
  spdlog::info("{}", describe_scan_source(setup));

  // Without LCM the process waits for SIGINT/SIGTERM itself; block them before any thread starts.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  if (no_lcm) pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  ::signal(SIGPIPE, SIG_IGN);
  std::unique_ptr<ServiceRuntime> runtime;
  if (!no_lcm) runtime = std::make_unique<ServiceRuntime>("lms100_emulator", lcm_url);

  Lms100Emulator emulator(setup.emulator, std::move(source));
  emulator.start();
  spdlog::info("{}", describe_device(setup, emulator.port()));
  std::optional<FaultCommandThread> control;
  if (control_stdin) control.emplace(STDIN_FILENO, emulator.faults(), report_fault_command);

  int rc = 0;
  if (runtime) {
    runtime->add_periodic(0.5, [&] {
      for (const auto& [name, value] : heartbeat_counters(emulator.stats())) runtime->counter(name) = value;
      runtime->set_state(heartbeat_t::STATE_OK, fmt::format("port {}", emulator.port()));
    });
    rc = runtime->run();
  } else {
    int signal_number = 0;
    sigwait(&stop_signals, &signal_number);
  }
  control.reset();
  emulator.stop();
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "lms100_emulator",
      "SICK LMS100 emulator: CoLa-A or CoLa-B over TCP, test pattern or rendered world, fault injection", "");
  cli.app.get_option("--config")
      ->description(
          "emulator config (keys in emulator_config_loader.hpp, world_file, map_T_laser, render {...})");
  refloc::EmulatorOverrides o;
  bool control_stdin = false, no_lcm = false;
  CLI::App& app = cli.app;
  app.add_option("--bind", o.bind_address, "address to listen on (default 127.0.0.1)");
  app.add_option("--protocol", o.protocol, "cola_a (default) or cola_b")
      ->check(CLI::IsMember({"cola_a", "cola_b"}));
  app.add_option("--port", o.port, "TCP port (2111, CoLa-B 2112; 0 any)")->check(CLI::Range(0, 65535));
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
  app.add_option("--startup-status-scans", o.startup_status_scans, "scans with status 1 0 after sEN");
  app.add_flag("--control-stdin", control_stdin, "fault commands from stdin (drop N, stall MS, close, ...)");
  app.add_flag("--no-lcm", no_lcm, "no HEARTBEAT (no LCM needed)");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::read_standalone_config(f); });
  return cli.run(argc, argv,
                 [&] { return refloc::run(cli.config_path, o, control_stdin, no_lcm, cli.lcm_url); });
}
