// robot_sim: the simulated robot. CMD_VEL (twist_t) drives a Mecanum plant (RobotSimNode);
// it publishes WHEEL_ENCODERS (wheel_encoders_t) and GROUND_TRUTH (pose2d_t) at 100 Hz
// and, given a world, serves an emulated LMS100 on TCP that renders the world from the
// laser's true, moving pose beam by beam.

#include "common/clock.hpp"
#include "common/node_event_report.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "robot_sim/robot_laser.hpp"
#include "robot_sim/robot_sim_node.hpp"
#include "robot_sim/sim_setup.hpp"

#include <CLI/CLI.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <memory>

namespace refloc {
namespace {

pose2d_t ground_truth_message(const TruePose& truth) {
  pose2d_t msg{};
  msg.utime = truth.utime;
  msg.x = truth.map_T_robot.x;
  msg.y = truth.map_T_robot.y;
  msg.theta = truth.map_T_robot.theta;
  msg.status = pose2d_t::STATUS_OK;
  return msg;
}

wheel_encoders_t encoders_message(const EncoderSample& sample) {
  wheel_encoders_t msg{};
  msg.utime = sample.utime;
  for (size_t i = 0; i < 4; ++i) msg.ticks[i] = sample.ticks[i];
  return msg;
}

int run(const ServiceCommandLine& cli, const SimOverrides& overrides) {
  const RobotConfig robot = load_robot_config(cli.robot_path);
  const SimSetup setup = load_sim_setup(cli.config_path, overrides);
  ServiceRuntime runtime("robot_sim", cli.lcm_url);
  RobotSimNode node(robot, setup.plant, now_utime());

  const std::unique_ptr<Lms100Emulator> laser =
      make_robot_laser(setup, [&node](int64_t utime) { return node.map_T_laser_at(utime); });
  if (laser) {
    laser->start();
    spdlog::info("LMS100 emulator on {}:{} rendering {}", setup.emulator.bind_address, laser->port(),
                 setup.world_path);
    runtime.add_periodic(0.5, [&] {
      const Lms100EmulatorStats s = laser->stats();
      runtime.counter("laser_clients_accepted") = static_cast<int64_t>(s.clients_accepted);
      runtime.counter("laser_scans_sent") = static_cast<int64_t>(s.scan_telegrams_sent);
      runtime.counter("laser_poses_outside_history") =
          static_cast<int64_t>(node.laser_poses_outside_history());
    });
  } else {
    spdlog::info("no world: running without the emulated LMS100");
  }

  runtime.subscribe<twist_t>(setup.command_channel, [&](const twist_t& msg) {
    node.on_command({msg.vx, msg.vy, msg.wz}, now_utime());
    report_events(runtime, node.events());
  });
  runtime.add_periodic(1.0 / setup.encoder_rate, [&] {
    const EncoderSample sample = node.encoder_tick(now_utime());
    runtime.publish("WHEEL_ENCODERS", encoders_message(sample));
    if (sample.command_timed_out) ++runtime.counter("command_timeouts");
  });
  runtime.add_periodic(1.0 / setup.ground_truth_rate, [&] {
    runtime.publish("GROUND_TRUTH", ground_truth_message(node.ground_truth_tick(now_utime())));
  });
  const int rc = runtime.run();
  if (laser) laser->stop();
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "robot_sim", "Simulated Mecanum robot: CMD_VEL -> WHEEL_ENCODERS, GROUND_TRUTH, emulated LMS100 on TCP",
      "");
  cli.add_robot_option("robot geometry file (JSON)");
  refloc::SimOverrides o;
  auto& app = cli.app;
  app.add_option("--world", o.world_path, "world file for the emulated LMS100 (overrides world_file)");
  app.add_option("--port", o.port, "LMS100 TCP port (0 = any free port)")->check(CLI::Range(0, 65535));
  app.add_option("--sensor-bind-address", o.sensor_bind_address,
                 "address the LMS100 emulator listens on (default 127.0.0.1; the computer's LAN address "
                 "when lms100_driver runs on another computer)");
  app.add_flag("--no-laser", o.no_laser, "run without the emulated LMS100");
  cli.set_config_reader([](const refloc::JsonConfig& f) { refloc::parse_sim_setup(f, "."); });
  return cli.run(argc, argv, [&] { return refloc::run(cli, o); });
}
