#include "mount_calibration.hpp"

#include "common/angles.hpp"

#include <ceres/ceres.h>

#include <cmath>

namespace refloc {
namespace {

/// Whitened residual L (R_X t_B - s t_A - (R_B - I) t_X), L^T L = Cov^-1.
struct HandEyeResidual {
  Eigen::Vector2d t_a;
  Eigen::Vector2d t_b;
  double theta_b;
  Eigen::Matrix2d whitening;

  template <class T>
  bool operator()(const T* mount, const T* scale, T* residual) const {
    const T c = ceres::cos(mount[2]);
    const T s = ceres::sin(mount[2]);
    const double cb = std::cos(theta_b) - 1.0;
    const double sb = std::sin(theta_b);
    const T rx = c * t_b.x() - s * t_b.y() - scale[0] * t_a.x() - (cb * mount[0] - sb * mount[1]);
    const T ry = s * t_b.x() + c * t_b.y() - scale[0] * t_a.y() - (sb * mount[0] + cb * mount[1]);
    residual[0] = whitening(0, 0) * rx + whitening(0, 1) * ry;
    residual[1] = whitening(1, 0) * rx + whitening(1, 1) * ry;
    return true;
  }
};

Eigen::Matrix2d residual_covariance(const MountWindow& w, const Pose2& x, const OdometryNoise& noise) {
  const Eigen::Matrix2d r_x = x.rotation();
  const Eigen::Matrix3d& cov_b = w.laser_first_T_last.covariance;
  const double tb = w.laser_first_T_last.pose.theta;
  const Eigen::Vector2d d_rb_tx(-std::sin(tb) * x.x - std::cos(tb) * x.y,
                                std::cos(tb) * x.x - std::sin(tb) * x.y);
  // Cross terms of t_B and theta_B are kept: both come from the same two fixes.
  Eigen::Matrix<double, 2, 3> j;
  j.leftCols<2>() = r_x;
  j.col(2) = -d_rb_tx;
  Eigen::Matrix2d cov = j * cov_b * j.transpose();
  cov += increment_covariance(w.odometry_first_T_last, noise).topLeftCorner<2, 2>();
  return cov + Eigen::Matrix2d::Identity() * 1e-12;  // never singular for a window without motion
}

Eigen::Matrix2d whitening_of(const Eigen::Matrix2d& cov) {
  // L = chol(Cov^-1)^T so that |L r|^2 = r^T Cov^-1 r.
  const Eigen::Matrix2d info = cov.inverse();
  return Eigen::LLT<Eigen::Matrix2d>(info).matrixU();
}

struct Solution {
  double mount[3];
  double scale = 1.0;
  double cost = 0.0;
  bool converged = false;
  std::string summary;
};

void solve(const std::vector<MountWindow>& windows, const MountCalibrationOptions& o, const Pose2& weights_at,
           Solution& sol, ceres::Problem& problem) {
  for (const MountWindow& w : windows) {
    auto* f = new HandEyeResidual{w.odometry_first_T_last.translation(),
                                  w.laser_first_T_last.pose.translation(), w.laser_first_T_last.pose.theta,
                                  whitening_of(residual_covariance(w, weights_at, o.odometry_noise))};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<HandEyeResidual, 2, 3, 1>(f), nullptr, sol.mount,
                             &sol.scale);
  }
  if (!o.estimate_translation_scale) problem.SetParameterBlockConstant(&sol.scale);
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  sol.cost = summary.final_cost;
  sol.converged = summary.IsSolutionUsable() && summary.termination_type == ceres::CONVERGENCE;
  sol.summary = summary.BriefReport();
}

}  // namespace

MountCalibrationResult calibrate_mount(const std::vector<MountWindow>& windows,
                                       const MountCalibrationOptions& o) {
  MountCalibrationResult result;
  result.windows = windows.size();
  for (const MountWindow& w : windows) {
    const double turned = std::abs(w.laser_first_T_last.pose.theta);
    result.total_rotation_rad += turned;
    if (turned < 0.05) result.total_translation_m += w.laser_first_T_last.pose.translation().norm();
  }
  if (result.total_rotation_rad < o.min_total_rotation_rad) {
    result.message = "the drive turned " + std::to_string(result.total_rotation_rad) +
                     " rad, need >= " + std::to_string(o.min_total_rotation_rad) +
                     " (rotate in place): mount x, y not observable";
    return result;
  }
  if (result.total_translation_m < o.min_total_translation_m) {
    result.message = "the drive went " + std::to_string(result.total_translation_m) +
                     " m straight, need >= " + std::to_string(o.min_total_translation_m) +
                     " (straight legs): mount yaw not observable";
    return result;
  }
  Solution sol;
  sol.mount[0] = o.initial_robot_T_laser.x;
  sol.mount[1] = o.initial_robot_T_laser.y;
  sol.mount[2] = o.initial_robot_T_laser.theta;
  {
    ceres::Problem first;
    solve(windows, o, o.initial_robot_T_laser, sol, first);
  }
  ceres::Problem problem;  // weights re-evaluated at the first solution
  solve(windows, o, Pose2{sol.mount[0], sol.mount[1], sol.mount[2]}, sol, problem);
  result.message = sol.summary;
  if (!sol.converged) return result;

  ceres::Covariance::Options cov_options;
  ceres::Covariance covariance(cov_options);
  std::vector<std::pair<const double*, const double*>> blocks{{sol.mount, sol.mount}};
  if (o.estimate_translation_scale) blocks.emplace_back(&sol.scale, &sol.scale);
  if (!covariance.Compute(blocks, &problem)) {
    result.message = "the covariance is rank deficient: the drive does not observe the mount";
    return result;
  }
  const double dof = 2.0 * static_cast<double>(windows.size()) - (o.estimate_translation_scale ? 4.0 : 3.0);
  result.chi2_per_dof = 2.0 * sol.cost / dof;  // Ceres' cost is chi^2 / 2
  const double inflate = std::max(1.0, result.chi2_per_dof);
  double mount_cov[9];
  covariance.GetCovarianceBlock(sol.mount, sol.mount, mount_cov);
  for (int i = 0; i < 9; ++i) result.covariance(i / 3, i % 3) = mount_cov[i] * inflate;
  if (o.estimate_translation_scale) {
    double scale_var = 0.0;
    covariance.GetCovarianceBlock(&sol.scale, &sol.scale, &scale_var);
    result.translation_scale_sigma = std::sqrt(scale_var * inflate);
  }
  result.robot_T_laser = Pose2{sol.mount[0], sol.mount[1], wrap_angle(sol.mount[2])};
  result.translation_scale = sol.scale;
  result.ok = true;
  return result;
}

std::vector<MountWindow> mount_windows(const CalibrationDrive& drive, const Pose2& configured_robot_T_laser,
                                       const WindowOptions& options) {
  std::vector<MountWindow> out;
  for (const FixWindow& w : select_fix_windows(drive.laser_fixes, options)) {
    const auto odom_first =
        interpolate_pose(drive.odometry, drive.laser_fixes[w.first].utime, options.max_fix_gap_s);
    const auto odom_last =
        interpolate_pose(drive.odometry, drive.laser_fixes[w.last].utime, options.max_fix_gap_s);
    if (!odom_first || !odom_last) continue;  // no odometry around the fix: nothing to compare
    MountWindow m;
    m.odometry_first_T_last = odom_first->inverse() * *odom_last;
    m.laser_first_T_last = relative_pose(compose_mount(drive.laser_fixes[w.first], configured_robot_T_laser),
                                         compose_mount(drive.laser_fixes[w.last], configured_robot_T_laser));
    out.push_back(m);
  }
  return out;
}

}  // namespace refloc
