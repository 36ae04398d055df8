// refloc-calibrate-mount: the laser mount robot_T_laser (x, y, yaw) from a calibration drive
// (rotation in place plus straight legs) recorded in an LCM log: hand-eye calibration of
// ODOMETRY against LASER_POSE (see mount_calibration.hpp). Prints the robot.json snippet.

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "mount_command.hpp"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{
      "refloc-calibrate-mount: estimate robot.json's laser_mount from a calibration drive's LCM log"};
  refloc::add_version_flag(app, "refloc-calibrate-mount");
  refloc::MountCommandOptions o;
  o.robot_path = refloc::shipped_path(o.robot_path);  // any working directory
  app.add_option("--log", o.log_path, "LCM log of the drive (ODOMETRY, LASER_POSE)")->required();
  app.add_option("--robot", o.robot_path, "robot file the services ran with (configured mount, noise)")
      ->capture_default_str();
  app.add_option("--json", o.json_path, "also write the result to this JSON file");
  app.add_option("--odometry-channel", o.channels.odometry)->capture_default_str();
  app.add_option("--laser-pose-channel", o.channels.laser_pose)->capture_default_str();
  app.add_option("--window-translation-m", o.windows.min_translation_m, "laser translation closing a window")
      ->check(CLI::Range(0.01, 10.0))
      ->capture_default_str();
  app.add_option("--window-rotation-rad", o.windows.min_rotation_rad, "laser rotation closing a window")
      ->check(CLI::Range(0.01, 3.0))
      ->capture_default_str();
  app.add_option("--window-max-s", o.windows.max_duration_s, "longest window")
      ->check(CLI::Range(0.05, 60.0))
      ->capture_default_str();
  app.add_option("--method", o.method,
                 "direct: every fix, segments with own start poses; hand-eye: A X = X B")
      ->check(CLI::IsMember({"direct", "hand-eye"}))
      ->capture_default_str();
  app.add_option("--segment-s", o.segment_s, "direct: segment length")
      ->check(CLI::Range(0.2, 60.0))
      ->capture_default_str();
  app.add_flag("!--no-translation-scale", o.estimate_translation_scale,
               "trust odometry's translation scale (do not estimate it)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  return refloc::guarded_main("refloc-calibrate-mount", [&] { return refloc::run_mount_calibration(o); });
}
