#include "mount_command.hpp"

#include "common/json_config.hpp"
#include "common/robot_config.hpp"
#include "mount_direct.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace refloc {

int run_mount_calibration(const MountCommandOptions& o) {
  const RobotConfig robot = load_robot_config(o.robot_path);
  CalibrationLogCounts counts;
  const CalibrationDrive drive = read_calibration_log(o.log_path, o.channels, counts);
  fmt::print("{}: {} {}, {} {} OK ({} not OK, unused), {} undecodable\n", o.log_path, counts.odometry,
             o.channels.odometry, counts.laser_fixes_ok, o.channels.laser_pose, counts.laser_fixes_not_ok,
             counts.undecodable);
  const std::vector<MountWindow> windows = mount_windows(drive, robot.robot_T_laser, o.windows);

  MountCalibrationOptions options;
  options.initial_robot_T_laser = robot.robot_T_laser;
  options.estimate_translation_scale = o.estimate_translation_scale;
  options.odometry_noise = robot.odometry_noise;
  DirectMountOptions direct;
  direct.mount = options;
  direct.segment_s = o.segment_s;
  direct.max_fix_gap_s = o.windows.max_fix_gap_s;
  const MountCalibrationResult r = o.method == "direct"
                                       ? calibrate_mount_direct(drive, robot.robot_T_laser, direct)
                                       : calibrate_mount(windows, options);
  const double duration_s =
      drive.laser_fixes.empty()
          ? 0.0
          : static_cast<double>(drive.laser_fixes.back().utime - drive.laser_fixes.front().utime) * 1e-6;
  fmt::print("{}: {} {} over {:.1f} s of fixes; turned {:.2f} rad, {:.2f} m straight\n", o.method, r.windows,
             o.method == "direct" ? "fixes" : "windows", duration_s, r.total_rotation_rad,
             r.total_translation_m);
  if (!r.ok) {
    fmt::print(stderr, "refloc-calibrate-mount: no mount: {}\n", r.message);
    return 1;
  }
  const Pose2& x = r.robot_T_laser;
  const double deg = 180.0 / M_PI;
  const double sx = std::sqrt(r.covariance(0, 0)), sy = std::sqrt(r.covariance(1, 1));
  const double st = std::sqrt(r.covariance(2, 2));
  fmt::print("robot_T_laser (1 sigma, least-squares covariance x max(1, chi2/dof)):\n");
  fmt::print("  x     = {:.5f} m   +- {:.5f} m   (configured {:.5f})\n", x.x, sx, robot.robot_T_laser.x);
  fmt::print("  y     = {:.5f} m   +- {:.5f} m   (configured {:.5f})\n", x.y, sy, robot.robot_T_laser.y);
  fmt::print("  theta = {:.4f} deg +- {:.4f} deg (configured {:.4f})\n", x.theta * deg, st * deg,
             robot.robot_T_laser.theta * deg);
  if (o.estimate_translation_scale) {
    fmt::print("odometry translation scale (laser / odometry) = {:.5f} +- {:.5f}\n", r.translation_scale,
               r.translation_scale_sigma);
  }
  fmt::print("chi2/dof = {:.3f}; {}\n", r.chi2_per_dof, r.message);
  fmt::print("robot.json:\n  \"laser_mount\": {{\"x_m\": {:.4f}, \"y_m\": {:.4f}, \"theta_rad\": {:.6f}}},\n",
             x.x, x.y, x.theta);
  if (!o.json_path.empty()) {
    const nlohmann::json j = {{"x_m", x.x},
                              {"y_m", x.y},
                              {"theta_rad", x.theta},
                              {"sigma_x_m", sx},
                              {"sigma_y_m", sy},
                              {"sigma_theta_rad", st},
                              {"translation_scale", r.translation_scale},
                              {"chi2_per_dof", r.chi2_per_dof},
                              {"windows", r.windows},
                              {"fix_duration_s", duration_s}};
    std::ofstream out(o.json_path);
    out << j.dump(2) << "\n";
    if (!out) throw ConfigError(o.json_path + ": cannot write");
  }
  return 0;
}

}  // namespace refloc
