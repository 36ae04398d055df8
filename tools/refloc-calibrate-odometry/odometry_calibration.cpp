#include "odometry_calibration.hpp"

#include "common/odometry_noise.hpp"
#include "mount_direct.hpp"

#include <ceres/ceres.h>

#include <cmath>

namespace refloc {
namespace {

struct OdometryResidual {
  const OdometryWindow* window;
  Eigen::Matrix3d whitening;

  bool operator()(const double* scales, double* residual) const {
    const Pose2 a = integrate_scaled(window->nominal_steps, scales[0], scales[1]);
    const BodyTwist e = se2_log(a.inverse() * window->laser_first_T_last.pose);
    const Eigen::Vector3d r = whitening * Eigen::Vector3d(e.vx, e.vy, e.wz);
    for (int i = 0; i < 3; ++i) residual[i] = r[i];
    return true;
  }
};

Eigen::Matrix3d whitening_of(const Eigen::Matrix3d& cov) {
  const Eigen::Matrix3d info = (cov + Eigen::Matrix3d::Identity() * 1e-12).inverse();
  return Eigen::LLT<Eigen::Matrix3d>(info).matrixU();
}

}  // namespace

Pose2 integrate_scaled(const std::vector<BodyTwist>& steps, double radius_scale, double geometry_scale) {
  Pose2 pose;
  for (const BodyTwist& d : steps) {
    pose = pose *
           se2_exp(BodyTwist{radius_scale * d.vx, radius_scale * d.vy, radius_scale / geometry_scale * d.wz});
  }
  return pose;
}

OdometryCalibrationResult calibrate_odometry(const std::vector<OdometryWindow>& windows,
                                             const OdometryCalibrationOptions& o) {
  OdometryCalibrationResult result;
  result.windows = windows.size();
  for (const OdometryWindow& w : windows) {
    result.total_rotation_rad += std::abs(w.laser_first_T_last.pose.theta);
    result.total_translation_m += w.laser_first_T_last.pose.translation().norm();
  }
  if (result.total_rotation_rad < o.min_total_rotation_rad ||
      result.total_translation_m < o.min_total_translation_m) {
    result.message = "the drive turned " + std::to_string(result.total_rotation_rad) + " rad and went " +
                     std::to_string(result.total_translation_m) +
                     " m; need >= " + std::to_string(o.min_total_rotation_rad) +
                     " rad and >= " + std::to_string(o.min_total_translation_m) +
                     " m: the scales are not observable";
    return result;
  }
  double scales[2] = {1.0, 1.0};
  ceres::Problem problem;
  for (const OdometryWindow& w : windows) {
    const Pose2 nominal = integrate_scaled(w.nominal_steps, 1.0, 1.0);
    const Eigen::Matrix3d cov =
        w.laser_first_T_last.covariance + increment_covariance(nominal, o.odometry_noise);
    auto* f = new OdometryResidual{&w, whitening_of(cov)};
    problem.AddResidualBlock(new ceres::NumericDiffCostFunction<OdometryResidual, ceres::CENTRAL, 3, 2>(f),
                             nullptr, scales);
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.message = summary.BriefReport();
  if (!summary.IsSolutionUsable() || summary.termination_type != ceres::CONVERGENCE) return result;

  ceres::Covariance covariance(ceres::Covariance::Options{});
  const std::vector<std::pair<const double*, const double*>> blocks{{scales, scales}};
  if (!covariance.Compute(blocks, &problem)) {
    result.message = "the covariance is rank deficient: the drive does not observe both scales";
    return result;
  }
  const double dof = 3.0 * static_cast<double>(windows.size()) - 2.0;
  result.chi2_per_dof = 2.0 * summary.final_cost / dof;
  double cov[4];
  covariance.GetCovarianceBlock(scales, scales, cov);
  const double inflate = std::max(1.0, result.chi2_per_dof);
  for (int i = 0; i < 4; ++i) result.covariance(i / 2, i % 2) = cov[i] * inflate;
  result.radius_scale = scales[0];
  result.geometry_scale = scales[1];
  result.ok = true;
  return result;
}

std::vector<OdometryWindow> odometry_windows(const CalibrationDrive& drive, const RobotConfig& nominal,
                                             const WindowOptions& options) {
  const MecanumKinematics kinematics(nominal);
  const auto& enc = drive.encoders;
  std::vector<OdometryWindow> out;
  for (const FixWindow& w : select_fix_windows(drive.laser_fixes, options)) {
    const int64_t t0 = drive.laser_fixes[w.first].utime;
    const int64_t t1 = drive.laser_fixes[w.last].utime;
    if (enc.empty() || enc.front().utime > t0 || enc.back().utime < t1) continue;  // not covered
    OdometryWindow window;
    bool gap = false;
    for (size_t k = 1; k < enc.size() && enc[k - 1].utime < t1; ++k) {
      const int64_t a = std::max(enc[k - 1].utime, t0);
      const int64_t b = std::min(enc[k].utime, t1);
      if (b <= a) continue;
      const double step_s = static_cast<double>(enc[k].utime - enc[k - 1].utime) * 1e-6;
      if (step_s > options.max_fix_gap_s) gap = true;
      // The part of this encoder step inside the window, wheels taken as turning evenly.
      const double fraction = static_cast<double>(b - a) * 1e-6 / step_s;
      const auto angle = wheel_angle_delta(enc[k - 1], enc[k], nominal.encoder_ticks_per_rev);
      const BodyTwist d = kinematics.forward(angle);
      window.nominal_steps.push_back(BodyTwist{d.vx * fraction, d.vy * fraction, d.wz * fraction});
    }
    if (gap) continue;
    window.laser_first_T_last = relative_pose(drive.laser_fixes[w.first], drive.laser_fixes[w.last]);
    out.push_back(std::move(window));
  }
  return out;
}

std::vector<TimedPose> encoder_odometry(const std::vector<EncoderSample>& encoders,
                                        const RobotConfig& nominal) {
  const MecanumKinematics kinematics(nominal);
  std::vector<TimedPose> out;
  Pose2 odom_T_robot;
  for (size_t k = 0; k < encoders.size(); ++k) {
    if (k > 0) {
      const auto angle = wheel_angle_delta(encoders[k - 1], encoders[k], nominal.encoder_ticks_per_rev);
      odom_T_robot = odom_T_robot * se2_exp(kinematics.forward(angle));
    }
    out.push_back({encoders[k].utime, odom_T_robot, Eigen::Matrix3d::Zero()});
  }
  return out;
}

OdometryCalibrationResult calibrate_odometry_direct(const CalibrationDrive& drive, const RobotConfig& nominal,
                                                    const Pose2& configured_robot_T_laser,
                                                    const Pose2& robot_T_laser, double segment_s) {
  CalibrationDrive from_encoders = drive;
  from_encoders.odometry = encoder_odometry(drive.encoders, nominal);
  DirectMountOptions o;
  o.mount.initial_robot_T_laser = robot_T_laser;
  o.mount.odometry_noise = nominal.odometry_noise;
  o.segment_s = segment_s;
  o.hold_mount = true;
  const MountCalibrationResult m = calibrate_mount_direct(from_encoders, configured_robot_T_laser, o);
  OdometryCalibrationResult result;
  result.ok = m.ok;
  result.message = m.message;
  result.windows = m.windows;
  result.total_rotation_rad = m.total_rotation_rad;
  result.total_translation_m = m.total_translation_m;
  result.chi2_per_dof = m.chi2_per_dof;
  if (!m.ok) return result;
  // (s_r, s_k) = (s, s / h): covariance through the Jacobian.
  const double s = m.translation_scale, h = m.heading_scale;
  result.radius_scale = s;
  result.geometry_scale = s / h;
  Eigen::Matrix2d j;
  j << 1.0, 0.0, 1.0 / h, -s / (h * h);
  result.covariance = j * m.scales_covariance * j.transpose();
  return result;
}

RobotConfig corrected_robot(const RobotConfig& nominal, double radius_scale, double geometry_scale) {
  RobotConfig r = nominal;
  r.wheel_radius *= radius_scale;
  r.half_wheelbase_lx *= geometry_scale;
  r.half_track_ly *= geometry_scale;
  return r;
}

}  // namespace refloc
