#include "odometry_command.hpp"

#include "common/json_config.hpp"
#include "common/robot_config.hpp"
#include "fix_truth_check.hpp"
#include "odometry_calibration.hpp"
#include "odometry_direct.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>

namespace refloc {
namespace {

int report_odometry_calibration(const OdometryCommandOptions& o, const RobotConfig& robot,
                                const OdometryCalibrationResult& r);

void print_fix_errors(const OdometryCommandOptions& o, const RobotConfig& robot,
                      const CalibrationDrive& drive, const Pose2& mount) {
  CalibrationChannels channels = o.channels;
  channels.laser_pose = o.truth_channel;
  CalibrationLogCounts counts;
  const CalibrationDrive truth = read_calibration_log(o.log_path, channels, counts);
  const FixTruthReport r = compare_fixes_with_truth(drive.laser_fixes, truth.laser_fixes, robot.robot_T_laser,
                                                    o.true_robot_T_laser.value_or(mount));
  fmt::print(
      "fixes against {} ({} fixes): mean error ({:+.2f}, {:+.2f}) mm, sigma ({:.2f}, {:.2f}) mm, "
      "{:.3f} mrad; lag-1 correlation {:.3f}\n",
      o.truth_channel, r.fixes, r.mean_x_m * 1e3, r.mean_y_m * 1e3, r.sigma_x_m * 1e3, r.sigma_y_m * 1e3,
      r.sigma_theta_rad * 1e3, r.lag1_correlation);
  fmt::print("  similarity fit over +-{:.2f} x +-{:.2f} m: expansion {:+.4f} %, rotation {:+.4f} mrad\n",
             r.half_extent_x_m, r.half_extent_y_m, r.expansion * 100.0, r.rotation_rad * 1e3);
}

}  // namespace

int run_odometry_calibration(const OdometryCommandOptions& o) {
  const RobotConfig robot = load_robot_config(o.robot_path);
  CalibrationLogCounts counts;
  CalibrationDrive drive = read_calibration_log(o.log_path, o.channels, counts);
  fmt::print("{}: {} {}, {} {} OK ({} not OK, unused), {} undecodable\n", o.log_path, counts.encoders,
             o.channels.encoders, counts.laser_fixes_ok, o.channels.laser_pose, counts.laser_fixes_not_ok,
             counts.undecodable);
  const Pose2 mount = o.robot_T_laser.value_or(robot.robot_T_laser);
  if (!o.truth_channel.empty()) print_fix_errors(o, robot, drive, mount);
  if (o.method == "direct") {
    DirectOdometryOptions direct;
    direct.segment_s = o.segment_s;
    return report_odometry_calibration(
        o, robot, calibrate_odometry_exact(drive, robot, robot.robot_T_laser, mount, direct));
  }
  if (o.method == "direct-endpoint") {
    const OdometryCalibrationResult r =
        calibrate_odometry_direct(drive, robot, robot.robot_T_laser, mount, o.segment_s);
    return report_odometry_calibration(o, robot, r);
  }
  if (o.robot_T_laser) {
    // LASER_POSE = map_T_laser * configured^-1; re-read it with the given mount.
    const Pose2 correction = robot.robot_T_laser * o.robot_T_laser->inverse();
    for (TimedPose& fix : drive.laser_fixes) fix = compose_mount(fix, correction);
  }
  const std::vector<OdometryWindow> windows = odometry_windows(drive, robot, o.windows);
  OdometryCalibrationOptions options;
  options.odometry_noise = robot.odometry_noise;
  return report_odometry_calibration(o, robot, calibrate_odometry(windows, options));
}

namespace {

int report_odometry_calibration(const OdometryCommandOptions& o, const RobotConfig& robot,
                                const OdometryCalibrationResult& r) {
  fmt::print("{}: {} {}; turned {:.2f} rad, drove {:.2f} m\n", o.method, r.windows,
             o.method == "direct" ? "fixes" : "windows", r.total_rotation_rad, r.total_translation_m);
  if (!r.ok) {
    fmt::print(stderr, "refloc-calibrate-odometry: no calibration: {}\n", r.message);
    return 1;
  }
  const double sr = std::sqrt(r.covariance(0, 0)), sk = std::sqrt(r.covariance(1, 1));
  const RobotConfig fixed = corrected_robot(robot, r.radius_scale, r.geometry_scale);
  fmt::print("1 sigma from the least-squares covariance x max(1, chi2/dof):\n");
  fmt::print("  wheel radius scale = {:.5f} +- {:.5f} ({:+.3f} %)\n", r.radius_scale, sr,
             (r.radius_scale - 1.0) * 100.0);
  fmt::print("  (lx + ly) scale    = {:.5f} +- {:.5f} ({:+.3f} %)\n", r.geometry_scale, sk,
             (r.geometry_scale - 1.0) * 100.0);
  fmt::print("chi2/dof = {:.3f}, correlation factor {:.2f}; {}\n", r.chi2_per_dof, r.correlation_factor,
             r.message);
  fmt::print("robot.json (only lx + ly is observable; lx, ly keep their ratio):\n");
  fmt::print(
      "  \"wheel_radius_m\": {:.6f},\n  \"half_wheelbase_lx_m\": {:.6f},\n  \"half_track_ly_m\": {:.6f},\n",
      fixed.wheel_radius, fixed.half_wheelbase_lx, fixed.half_track_ly);
  if (!o.json_path.empty()) {
    const nlohmann::json j = {{"radius_scale", r.radius_scale},
                              {"sigma_radius_scale", sr},
                              {"geometry_scale", r.geometry_scale},
                              {"sigma_geometry_scale", sk},
                              {"wheel_radius_m", fixed.wheel_radius},
                              {"half_wheelbase_lx_m", fixed.half_wheelbase_lx},
                              {"half_track_ly_m", fixed.half_track_ly},
                              {"chi2_per_dof", r.chi2_per_dof},
                              {"correlation_factor", r.correlation_factor},
                              {"windows", r.windows}};
    std::ofstream out(o.json_path);
    out << j.dump(2) << "\n";
    if (!out) throw ConfigError(o.json_path + ": cannot write");
  }
  return 0;
}

}  // namespace

}  // namespace refloc
