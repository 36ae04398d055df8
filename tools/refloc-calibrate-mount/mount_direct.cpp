#include "mount_direct.hpp"

#include "common/angles.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>

namespace refloc {
namespace {

struct FixInSegment {
  Pose2 odometry_rel;  ///< odom_k_T_robot(t): odometry since the segment's start
  TimedPose map_T_laser;
  size_t segment = 0;
};

template <class T>
T wrapped(T a) {
  return ceres::atan2(ceres::sin(a), ceres::cos(a));
}

struct DirectResidual {
  Pose2 rel;
  Pose2 measured;
  Eigen::Matrix3d whitening;

  template <class T>
  bool operator()(const T* segment, const T* mount, const T* scales, T* residual) const {
    // map_T_robot = segment * (s * rel.t, h * rel.theta); map_T_laser = map_T_robot * mount.
    const T cs = ceres::cos(segment[2]), ss = ceres::sin(segment[2]);
    const T rx = scales[0] * rel.x, ry = scales[0] * rel.y;
    const T robot_x = segment[0] + cs * rx - ss * ry;
    const T robot_y = segment[1] + ss * rx + cs * ry;
    const T robot_theta = segment[2] + scales[1] * rel.theta;
    const T cr = ceres::cos(robot_theta), sr = ceres::sin(robot_theta);
    T e[3];
    e[0] = robot_x + cr * mount[0] - sr * mount[1] - measured.x;
    e[1] = robot_y + sr * mount[0] + cr * mount[1] - measured.y;
    e[2] = wrapped(robot_theta + mount[2] - measured.theta);
    for (int i = 0; i < 3; ++i)
      residual[i] = whitening(i, 0) * e[0] + whitening(i, 1) * e[1] + whitening(i, 2) * e[2];
    return true;
  }
};

std::vector<FixInSegment> segment_fixes(const CalibrationDrive& drive, const Pose2& configured,
                                        const DirectMountOptions& o, std::vector<Pose2>& segment_starts) {
  std::vector<FixInSegment> out;
  int64_t segment_start_utime = 0;
  int64_t previous_utime = 0;
  Pose2 odom_at_start;
  bool open = false;
  for (const TimedPose& fix : drive.laser_fixes) {
    const auto odom = interpolate_pose(drive.odometry, fix.utime, o.max_fix_gap_s);
    if (!odom) {
      open = false;  // no odometry here: the next fix starts a new segment
      continue;
    }
    const double since_start_s = static_cast<double>(fix.utime - segment_start_utime) * 1e-6;
    const double since_previous_s = static_cast<double>(fix.utime - previous_utime) * 1e-6;
    if (!open || since_start_s >= o.segment_s || since_previous_s > o.max_fix_gap_s) {
      segment_start_utime = fix.utime;
      odom_at_start = *odom;
      segment_starts.push_back(fix.pose);  // map_T_robot at the start, the configured mount's
      open = true;
    }
    previous_utime = fix.utime;
    out.push_back(
        {odom_at_start.inverse() * *odom, compose_mount(fix, configured), segment_starts.size() - 1});
  }
  return out;
}

Eigen::Matrix3d whitening_of(const FixInSegment& f, const OdometryNoise& noise) {
  Eigen::Matrix3d cov = f.map_T_laser.covariance;
  const Eigen::Matrix3d odo = increment_covariance(f.odometry_rel, noise);
  // Odometry's translation error is taken as isotropic, so its frame does not matter.
  const double translation_var = 0.5 * (odo(0, 0) + odo(1, 1));
  cov(0, 0) += translation_var;
  cov(1, 1) += translation_var;
  cov(2, 2) += odo(2, 2);
  const Eigen::Matrix3d info = (cov + Eigen::Matrix3d::Identity() * 1e-12).inverse();
  return Eigen::LLT<Eigen::Matrix3d>(info).matrixU();
}

}  // namespace

MountCalibrationResult calibrate_mount_direct(const CalibrationDrive& drive, const Pose2& configured,
                                              const DirectMountOptions& o) {
  const MountCalibrationOptions& m = o.mount;
  // The observability checks (and the totals printed) are the hand-eye windows'.
  const MountCalibrationOptions& check = m;
  MountCalibrationResult result;
  {
    const std::vector<MountWindow> windows = mount_windows(drive, configured, WindowOptions{});
    for (const MountWindow& w : windows) {
      const double turned = std::abs(w.laser_first_T_last.pose.theta);
      result.total_rotation_rad += turned;
      if (turned < 0.05) result.total_translation_m += w.laser_first_T_last.pose.translation().norm();
    }
  }
  if (result.total_rotation_rad < check.min_total_rotation_rad) {
    result.message = "the drive turned " + std::to_string(result.total_rotation_rad) +
                     " rad, need >= " + std::to_string(check.min_total_rotation_rad) +
                     " (rotate in place): mount x, y not observable";
    return result;
  }
  if (result.total_translation_m < check.min_total_translation_m) {
    result.message = "the drive went " + std::to_string(result.total_translation_m) +
                     " m straight, need >= " + std::to_string(check.min_total_translation_m) +
                     " (straight legs): mount yaw not observable";
    return result;
  }
  std::vector<Pose2> starts;
  const std::vector<FixInSegment> fixes = segment_fixes(drive, configured, o, starts);
  std::vector<std::array<double, 3>> segments(starts.size());
  for (size_t k = 0; k < starts.size(); ++k) segments[k] = {starts[k].x, starts[k].y, starts[k].theta};
  double mount[3] = {m.initial_robot_T_laser.x, m.initial_robot_T_laser.y, m.initial_robot_T_laser.theta};
  double scales[2] = {1.0, 1.0};  // s (odometry translation), h (odometry heading)
  ceres::Problem problem;
  for (const FixInSegment& f : fixes) {
    auto* r = new DirectResidual{f.odometry_rel, f.map_T_laser.pose, whitening_of(f, m.odometry_noise)};
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<DirectResidual, 3, 3, 3, 2>(r), nullptr,
                             segments[f.segment].data(), mount, scales);
  }
  if (o.hold_mount) problem.SetParameterBlockConstant(mount);
  if (!m.estimate_translation_scale) {
    problem.SetManifold(scales, new ceres::SubsetManifold(2, {0}));
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.windows = fixes.size();
  result.message = summary.BriefReport();
  if (!summary.IsSolutionUsable() || summary.termination_type != ceres::CONVERGENCE) return result;

  ceres::Covariance covariance(ceres::Covariance::Options{});
  std::vector<std::pair<const double*, const double*>> blocks{{scales, scales}};
  if (!o.hold_mount) blocks.emplace_back(mount, mount);
  if (!covariance.Compute(blocks, &problem)) {
    result.message = "the covariance is rank deficient: the drive does not observe the mount";
    return result;
  }
  const double parameters = 3.0 * static_cast<double>(segments.size()) + 5.0;
  const double dof = std::max(1.0, 3.0 * static_cast<double>(fixes.size()) - parameters);
  result.chi2_per_dof = 2.0 * summary.final_cost / dof;
  const double inflate = std::max(1.0, result.chi2_per_dof);
  double mount_cov[9] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (!o.hold_mount) covariance.GetCovarianceBlock(mount, mount, mount_cov);
  for (int i = 0; i < 9; ++i) result.covariance(i / 3, i % 3) = mount_cov[i] * inflate;
  double scale_cov[4];
  covariance.GetCovarianceBlock(scales, scales, scale_cov);
  result.translation_scale = scales[0];
  result.translation_scale_sigma = std::sqrt(scale_cov[0] * inflate);
  result.heading_scale = scales[1];
  for (int i = 0; i < 4; ++i) result.scales_covariance(i / 2, i % 2) = scale_cov[i] * inflate;
  result.robot_T_laser = Pose2{mount[0], mount[1], wrap_angle(mount[2])};
  result.ok = true;
  return result;
}

}  // namespace refloc
