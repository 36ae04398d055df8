#include "odometry_direct.hpp"

#include "common/angles.hpp"
#include "common/mecanum_kinematics.hpp"

#include <ceres/ceres.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>

namespace refloc {
namespace {

/// One fix in a segment: the nominal encoder steps since the previous fix of the segment.
struct FixTerm {
  std::vector<BodyTwist> steps;  ///< nominal body displacements [m, m, rad]
  Pose2 map_T_laser;             ///< measured
  Eigen::Matrix3d whitening;
};

struct Segment {
  Pose2 map_T_start;  ///< initial guess of the segment's start pose (robot)
  std::vector<FixTerm> fixes;
};

template <class T>
T wrapped(T a) {
  return ceres::atan2(ceres::sin(a), ceres::cos(a));
}

/// Every fix of one segment, odometry integrated with the scales from the segment's start pose.
struct SegmentResidual {
  const Segment* segment;
  Pose2 robot_T_laser;

  template <class T>
  bool operator()(T const* const* parameters, T* residual) const {
    const T* start = parameters[0];
    const T& radius_scale = parameters[1][0];
    const T heading_scale = radius_scale / parameters[1][1];  // s_r / s_k
    T x = start[0], y = start[1], theta = start[2];
    size_t out = 0;
    for (const FixTerm& f : segment->fixes) {
      for (const BodyTwist& d : f.steps) {
        // Exact SE(2) step: the translation turns by half the step's rotation and shortens by
        // sin(w/2)/(w/2) (series: w <= ~0.05 rad per encoder step).
        const T w = heading_scale * d.wz;
        const T chord = T(1.0) - w * w / 24.0;
        const T mid = theta + 0.5 * w;
        const T dx = chord * radius_scale * d.vx, dy = chord * radius_scale * d.vy;
        x += ceres::cos(mid) * dx - ceres::sin(mid) * dy;
        y += ceres::sin(mid) * dx + ceres::cos(mid) * dy;
        theta += w;
      }
      const T c = ceres::cos(theta), s = ceres::sin(theta);
      T e[3];
      e[0] = x + c * robot_T_laser.x - s * robot_T_laser.y - f.map_T_laser.x;
      e[1] = y + s * robot_T_laser.x + c * robot_T_laser.y - f.map_T_laser.y;
      e[2] = wrapped(theta + robot_T_laser.theta - f.map_T_laser.theta);
      for (int i = 0; i < 3; ++i)
        residual[out + i] = f.whitening(i, 0) * e[0] + f.whitening(i, 1) * e[1] + f.whitening(i, 2) * e[2];
      out += 3;
    }
    return true;
  }
};

/// The nominal body displacements between t0 and t1 (encoder steps cut at both ends, wheels
/// taken as turning evenly within a step); nullopt when the encoders do not cover the span or
/// one of their steps is longer than max_gap_s. next: search hint, advanced.
std::optional<std::vector<BodyTwist>> steps_between(const std::vector<EncoderSample>& enc, int64_t t0,
                                                    int64_t t1, const MecanumKinematics& kinematics,
                                                    int ticks_per_rev, double max_gap_s, size_t& next) {
  if (enc.empty() || enc.front().utime > t0 || enc.back().utime < t1) return std::nullopt;
  while (next > 1 && enc[next - 1].utime > t0) --next;
  next = std::max<size_t>(next, 1);
  while (next < enc.size() && enc[next].utime <= t0) ++next;
  std::vector<BodyTwist> steps;
  for (size_t k = next; k < enc.size() && enc[k - 1].utime < t1; ++k) {
    const int64_t a = std::max(enc[k - 1].utime, t0), b = std::min(enc[k].utime, t1);
    if (b <= a) continue;
    const double step_s = static_cast<double>(enc[k].utime - enc[k - 1].utime) * 1e-6;
    if (step_s > max_gap_s) return std::nullopt;
    const double fraction = static_cast<double>(b - a) * 1e-6 / step_s;
    const BodyTwist d = kinematics.forward(wheel_angle_delta(enc[k - 1], enc[k], ticks_per_rev));
    steps.push_back(BodyTwist{d.vx * fraction, d.vy * fraction, d.wz * fraction});
  }
  return steps;
}

Eigen::Matrix3d whitening_of(const Eigen::Matrix3d& fix_covariance, double path_m, double turned_rad,
                             const OdometryNoise& noise) {
  Eigen::Matrix3d cov = fix_covariance;
  // Odometry's translation error is taken as isotropic, so its frame does not matter.
  const double var_xy =
      noise.translation_variance_per_m * path_m + noise.translation_variance_per_rad * turned_rad;
  cov(0, 0) += var_xy;
  cov(1, 1) += var_xy;
  cov(2, 2) += noise.heading_variance_per_m * path_m + noise.heading_variance_per_rad * turned_rad;
  const Eigen::Matrix3d info = (cov + Eigen::Matrix3d::Identity() * 1e-12).inverse();
  return Eigen::LLT<Eigen::Matrix3d>(info).matrixU();
}

std::vector<Segment> make_segments(const CalibrationDrive& drive, const RobotConfig& nominal,
                                   const Pose2& configured, const Pose2& mount,
                                   const DirectOdometryOptions& o, OdometryCalibrationResult& totals) {
  const MecanumKinematics kinematics(nominal);
  std::vector<Segment> segments;
  size_t hint = 1;
  int64_t start_utime = 0;
  double path_m = 0.0, turned_rad = 0.0;
  const TimedPose* previous = nullptr;
  for (const TimedPose& fix : drive.laser_fixes) {
    const TimedPose map_T_laser = compose_mount(fix, configured);
    std::optional<std::vector<BodyTwist>> steps;
    const bool continues = previous != nullptr &&
                           static_cast<double>(fix.utime - previous->utime) * 1e-6 <= o.max_fix_gap_s &&
                           static_cast<double>(fix.utime - start_utime) * 1e-6 < o.segment_s;
    if (continues) {
      steps = steps_between(drive.encoders, previous->utime, fix.utime, kinematics,
                            nominal.encoder_ticks_per_rev, o.max_fix_gap_s, hint);
    }
    if (!steps) {  // a new segment starts at this fix
      segments.push_back({map_T_laser.pose * mount.inverse(), {}});
      steps.emplace();
      start_utime = fix.utime;
      path_m = turned_rad = 0.0;
    }
    for (const BodyTwist& d : *steps) {
      path_m += std::hypot(d.vx, d.vy);
      turned_rad += std::abs(d.wz);
    }
    segments.back().fixes.push_back(
        {std::move(*steps), map_T_laser.pose,
         whitening_of(map_T_laser.covariance, path_m, turned_rad, nominal.odometry_noise)});
    previous = &fix;
  }
  for (const Segment& s : segments) {
    for (const FixTerm& f : s.fixes) {
      for (const BodyTwist& d : f.steps) {
        totals.total_translation_m += std::hypot(d.vx, d.vy);
        totals.total_rotation_rad += std::abs(d.wz);
      }
    }
  }
  return segments;
}

/// 1 + 2 sum of the lag-k autocorrelations of the whitened residuals, pooled over x, y and
/// theta (so a component the weights make negligible does not dominate) and over pairs within a
/// segment, summed while positive.
double correlation_factor(const std::vector<std::vector<double>>& residuals_by_segment, size_t max_lag) {
  double variance = 0.0;
  size_t n = 0;
  for (const auto& r : residuals_by_segment) {
    for (double v : r) variance += v * v;
    n += r.size();
  }
  if (n == 0 || variance <= 0.0) return 1.0;
  variance /= static_cast<double>(n);
  double sum = 0.0;
  for (size_t lag = 1; lag <= max_lag; ++lag) {
    double product = 0.0;
    size_t pairs = 0;
    for (const auto& r : residuals_by_segment) {
      for (size_t i = 0; i + 3 * lag < r.size(); ++i) product += r[i] * r[i + 3 * lag];
      pairs += r.size() > 3 * lag ? r.size() - 3 * lag : 0;
    }
    if (pairs < 30) break;
    const double rho = product / static_cast<double>(pairs) / variance;
    if (rho <= 0.0) break;
    sum += rho;
  }
  return 1.0 + 2.0 * sum;
}

}  // namespace

OdometryCalibrationResult calibrate_odometry_exact(const CalibrationDrive& drive, const RobotConfig& nominal,
                                                   const Pose2& configured, const Pose2& mount,
                                                   const DirectOdometryOptions& o) {
  OdometryCalibrationResult result;
  std::vector<Segment> segments = make_segments(drive, nominal, configured, mount, o, result);
  for (const Segment& s : segments) result.windows += s.fixes.size();
  if (result.total_rotation_rad < o.min_total_rotation_rad ||
      result.total_translation_m < o.min_total_translation_m) {
    result.message = "the drive turned " + std::to_string(result.total_rotation_rad) + " rad and went " +
                     std::to_string(result.total_translation_m) +
                     " m; need >= " + std::to_string(o.min_total_rotation_rad) +
                     " rad and >= " + std::to_string(o.min_total_translation_m) +
                     " m: the scales are not observable";
    return result;
  }
  std::vector<std::array<double, 3>> starts(segments.size());
  double scales[2] = {1.0, 1.0};  // s_r, s_k
  ceres::Problem problem;
  std::vector<ceres::ResidualBlockId> blocks;
  for (size_t k = 0; k < segments.size(); ++k) {
    starts[k] = {segments[k].map_T_start.x, segments[k].map_T_start.y, segments[k].map_T_start.theta};
    auto* cost =
        new ceres::DynamicAutoDiffCostFunction<SegmentResidual, 5>(new SegmentResidual{&segments[k], mount});
    cost->AddParameterBlock(3);
    cost->AddParameterBlock(2);
    cost->SetNumResiduals(static_cast<int>(3 * segments[k].fixes.size()));
    blocks.push_back(problem.AddResidualBlock(cost, nullptr, starts[k].data(), scales));
  }
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_SCHUR;
  options.max_num_iterations = 100;
  options.function_tolerance = 1e-14;
  options.parameter_tolerance = 1e-14;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  result.message = summary.BriefReport();
  if (!summary.IsSolutionUsable() || summary.termination_type != ceres::CONVERGENCE) return result;

  ceres::Covariance covariance(ceres::Covariance::Options{});
  const std::vector<std::pair<const double*, const double*>> wanted{{scales, scales}};
  if (!covariance.Compute(wanted, &problem)) {
    result.message = "the covariance is rank deficient: the drive does not observe both scales";
    return result;
  }
  std::vector<std::vector<double>> residuals(blocks.size());
  for (size_t k = 0; k < blocks.size(); ++k) {
    residuals[k].resize(3 * segments[k].fixes.size());
    problem.EvaluateResidualBlock(blocks[k], false, nullptr, residuals[k].data(), nullptr);
  }
  const double dof = std::max(
      1.0, 3.0 * static_cast<double>(result.windows) - 3.0 * static_cast<double>(segments.size()) - 2.0);
  result.chi2_per_dof = 2.0 * summary.final_cost / dof;
  result.correlation_factor = correlation_factor(residuals, o.max_correlation_lag);
  double cov[4];
  covariance.GetCovarianceBlock(scales, scales, cov);
  // chi2/dof below 1 (the odometry noise model is pessimistic: 0.06-0.4 on the simulated drives)
  // does not shrink the sigma: with it, one of three runs was off by 3 sigma.
  const double inflate = std::max(1.0, result.chi2_per_dof) * result.correlation_factor;
  for (int i = 0; i < 4; ++i) result.covariance(i / 2, i % 2) = cov[i] * inflate;
  result.radius_scale = scales[0];
  result.geometry_scale = scales[1];
  result.ok = true;
  return result;
}

}  // namespace refloc
