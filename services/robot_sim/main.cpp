// robot_sim: the simulated robot. CMD_VEL (twist_t) drives a Mecanum plant;
// it publishes WHEEL_ENCODERS (wheel_encoders_t) and GROUND_TRUTH (pose2d_t) at
// 100 Hz and, when built with the LMS100 emulator, serves an emulated LMS100 on
// TCP that renders the world from the laser's true, moving pose beam by beam.

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "robot_sim/encoder_model.hpp"
#include "robot_sim/mecanum_plant.hpp"
#include "robot_sim/plant_config_file.hpp"
#include "robot_sim/pose_history.hpp"

#include "lms100_emulator/emulator_config_loader.hpp"
#include "lms100_emulator/lms100_emulator.hpp"
#include "lms100_emulator/scan_render_source.hpp"
#include "world_renderer/world_loader.hpp"

#include <CLI/CLI.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <filesystem>
#include <memory>
#include <optional>

namespace refloc {
namespace {

struct Options {
  std::string lcm_url;
  std::string robot_path = "deploy/config/robot.json";
  std::string config_path;
  std::string world_path;  ///< overrides the config's world_file
  bool no_laser = false;
  int port = -1;
  std::string sensor_bind_address;  ///< overrides /emulator/bind_address
};

struct SimSetup {
  PlantSetup plant;
  double encoder_rate = 100.0;       ///< [Hz]
  double ground_truth_rate = 100.0;  ///< [Hz]
  std::string world_path;            ///< empty: no laser
  Lms100EmulatorConfig emulator;
  sim::ScanRenderConfig render;
  std::string command_channel = "CMD_VEL";
};

SimSetup load_setup(const Options& o) {
  SimSetup s;
  if (!o.config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(o.config_path);
    s.plant = parse_plant_setup(file);
    s.encoder_rate = file.number("/encoder_rate_hz", s.encoder_rate, 1.0, 1000.0);
    s.ground_truth_rate = file.number("/ground_truth_rate_hz", s.ground_truth_rate, 1.0, 1000.0);
    s.command_channel = file.string("/command_channel", s.command_channel);
    const std::string world = file.string("/world_file", "");
    if (!world.empty()) s.world_path = (std::filesystem::path(o.config_path).parent_path() / world).string();
    if (file.has("/render")) s.render = sim::parse_scan_render_config(file, "/render");
    if (file.has("/emulator")) {
      const JsonConfig emulator(file.subtree("/emulator"), file.source() + " /emulator");
      s.emulator = parse_emulator_config(emulator);
      emulator.reject_unknown_keys();
    }
    file.reject_unknown_keys();
  }
  if (!o.world_path.empty()) s.world_path = o.world_path;
  if (o.no_laser) s.world_path.clear();
  if (o.port >= 0) s.emulator.port = static_cast<uint16_t>(o.port);
  if (!o.sensor_bind_address.empty()) s.emulator.bind_address = o.sensor_bind_address;
  return s;
}

pose2d_t ground_truth_message(int64_t utime, const Pose2& pose) {
  pose2d_t msg{};
  msg.utime = utime;
  msg.x = pose.x;
  msg.y = pose.y;
  msg.theta = pose.theta;
  msg.status = pose2d_t::STATUS_OK;
  return msg;
}

int run(const Options& o) {
  const RobotConfig robot = load_robot_config(o.robot_path);
  const SimSetup setup = load_setup(o);
  ServiceRuntime runtime("robot_sim", o.lcm_url);

  MecanumPlant plant(robot, setup.plant.plant, setup.plant.initial_map_T_robot, now_utime());
  const EncoderModel encoders(robot.encoder_ticks_per_rev, setup.plant.encoder_start_ticks);
  auto laser_poses = std::make_shared<PoseHistory>(2000);  // 2 s at 1 kHz
  laser_poses->add(plant.utime(), plant.map_T_robot() * robot.robot_T_laser);

  std::unique_ptr<Lms100Emulator> emulator;
  if (!setup.world_path.empty()) {
    auto world = std::make_shared<const sim::World>(sim::load_world(setup.world_path));
    ScanSource source = sim::make_rendered_scan_source(
        world, [laser_poses](int64_t utime) { return laser_poses->at(utime); }, setup.render,
        setup.emulator.random_seed);
    emulator = std::make_unique<Lms100Emulator>(setup.emulator, std::move(source));
    emulator->start();
    spdlog::info("LMS100 emulator on {}:{} rendering {}", setup.emulator.bind_address, emulator->port(),
                 setup.world_path);
  } else {
    spdlog::info("no world: running without the emulated LMS100");
  }

  runtime.subscribe<twist_t>(setup.command_channel, [&](const twist_t& msg) {
    if (!std::isfinite(msg.vx) || !std::isfinite(msg.vy) || !std::isfinite(msg.wz)) {
      ++runtime.counter("invalid_commands");
      return;
    }
    // Age is judged from the time of receipt, as a motor controller does: no clock sync needed.
    plant.command({msg.vx, msg.vy, msg.wz}, now_utime());
  });
  // Advance in internal steps, recording the laser pose of each for the renderer.
  const auto step_us = static_cast<int64_t>(std::llround(setup.plant.plant.step * 1e6));
  const auto advance = [&] {
    const int64_t now = now_utime();
    while (plant.utime() + step_us <= now) {
      plant.advance_to(plant.utime() + step_us);
      laser_poses->add(plant.utime(), plant.map_T_robot() * robot.robot_T_laser);
    }
  };
  bool was_stale = true;
  runtime.add_periodic(1.0 / setup.encoder_rate, [&] {
    advance();
    wheel_encoders_t msg{};
    msg.utime = plant.utime();
    const std::array<int32_t, 4> counts = encoders.counts(plant.wheel_angles());
    for (size_t i = 0; i < 4; ++i) msg.ticks[i] = counts[i];
    runtime.publish("WHEEL_ENCODERS", msg);
    if (plant.command_stale() && !was_stale) ++runtime.counter("command_timeouts");
    was_stale = plant.command_stale();
  });
  runtime.add_periodic(1.0 / setup.ground_truth_rate, [&] {
    advance();
    runtime.publish("GROUND_TRUTH", ground_truth_message(plant.utime(), plant.map_T_robot()));
  });
  if (emulator) {
    runtime.add_periodic(0.5, [&] {
      const Lms100EmulatorStats s = emulator->stats();
      runtime.counter("laser_clients_accepted") = static_cast<int64_t>(s.clients_accepted);
      runtime.counter("laser_scans_sent") = static_cast<int64_t>(s.scan_telegrams_sent);
    });
  }
  const int rc = runtime.run();
  if (emulator) emulator->stop();
  return rc;
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "robot_sim", "Simulated Mecanum robot: CMD_VEL -> WHEEL_ENCODERS, GROUND_TRUTH, emulated LMS100 on TCP",
      "");
  cli.add_robot_option("robot geometry file (JSON)");
  refloc::Options o;
  auto& app = cli.app;
  app.add_option("--world", o.world_path, "world file for the emulated LMS100 (overrides world_file)");
  app.add_option("--port", o.port, "LMS100 TCP port (0 = any free port)")->check(CLI::Range(0, 65535));
  app.add_option("--sensor-bind-address", o.sensor_bind_address,
                 "address the LMS100 emulator listens on (default 127.0.0.1; the computer's LAN address "
                 "when lms100_driver runs on another computer)");
  app.add_flag("--no-laser", o.no_laser, "run without the emulated LMS100");
  return cli.run(argc, argv, [&] {
    o.lcm_url = cli.lcm_url;
    o.robot_path = cli.robot_path;
    o.config_path = cli.config_path;
    return refloc::run(o);
  });
}
