// refloc-calibrate-odometry: the wheel radius and (lx + ly) scales of the Mecanum base from a
// drive's WHEEL_ENCODERS against its laser fixes (see odometry_calibration.hpp). Prints the
// corrected robot.json values.

#include "common/guarded_main.hpp"
#include "common/program_version.hpp"
#include "odometry_command.hpp"

#include <CLI/CLI.hpp>

#include <vector>

int main(int argc, char** argv) {
  CLI::App app{"refloc-calibrate-odometry: estimate wheel radius and lx + ly from a drive's LCM log"};
  refloc::add_version_flag(app, "refloc-calibrate-odometry");
  refloc::OdometryCommandOptions o;
  o.robot_path = refloc::shipped_path(o.robot_path);  // any working directory
  std::vector<double> mount, true_mount;
  app.add_option("--log", o.log_path, "LCM log of the drive (WHEEL_ENCODERS, LASER_POSE)")->required();
  app.add_option("--robot", o.robot_path, "robot file the services ran with (nominal geometry, mount)")
      ->capture_default_str();
  app.add_option("--laser-mount", mount,
                 "x_m,y_m,theta_rad to read LASER_POSE with (refloc-calibrate-mount's)")
      ->delimiter(',')
      ->expected(3);
  app.add_option("--method", o.method,
                 "direct: every fix, odometry integrated step by step, segments with own start poses; "
                 "direct-endpoint: refloc-calibrate-mount's model (end pose scaled, approximate on arcs); "
                 "windows: fix pairs")
      ->check(CLI::IsMember({"direct", "direct-endpoint", "windows"}))
      ->capture_default_str();
  app.add_option("--segment-s", o.segment_s,
                 "direct: segment length [s] (each segment has its own start pose)")
      ->check(CLI::Range(0.2, 3600.0))
      ->capture_default_str();
  app.add_option("--truth-channel", o.truth_channel,
                 "simulation: also print the fixes' errors against this true-pose channel (GROUND_TRUTH)");
  app.add_option("--true-mount", true_mount,
                 "simulation: x_m,y_m,theta_rad of the simulated robot's laser mount")
      ->delimiter(',')
      ->expected(3);
  app.add_option("--json", o.json_path, "also write the result to this JSON file");
  app.add_option("--encoders-channel", o.channels.encoders)->capture_default_str();
  app.add_option("--laser-pose-channel", o.channels.laser_pose)->capture_default_str();
  app.add_option("--window-max-s", o.windows.max_duration_s, "longest window")
      ->check(CLI::Range(0.05, 60.0))
      ->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : refloc::kExitUsageError;  // --help/--version: 0
  }
  if (mount.size() == 3) o.robot_T_laser = refloc::Pose2{mount[0], mount[1], mount[2]};
  if (true_mount.size() == 3)
    o.true_robot_T_laser = refloc::Pose2{true_mount[0], true_mount[1], true_mount[2]};
  return refloc::guarded_main("refloc-calibrate-odometry",
                              [&] { return refloc::run_odometry_calibration(o); });
}
