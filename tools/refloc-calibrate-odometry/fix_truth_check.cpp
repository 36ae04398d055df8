#include "fix_truth_check.hpp"

#include "common/angles.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace refloc {

FixTruthReport compare_fixes_with_truth(const std::vector<TimedPose>& fixes,
                                        const std::vector<TimedPose>& truth, const Pose2& configured,
                                        const Pose2& true_mount) {
  struct Sample {
    Eigen::Vector2d truth;
    Eigen::Vector2d error;
    double heading_error;
  };
  std::vector<Sample> samples;
  for (const TimedPose& fix : fixes) {
    const auto t = interpolate_pose(truth, fix.utime, 0.05);
    if (!t) continue;
    // The fix re-read with the true mount: map_T_laser * true_robot_T_laser^-1.
    const Pose2 estimate = fix.pose * configured * true_mount.inverse();
    samples.push_back(
        {t->translation(), estimate.translation() - t->translation(), wrap_angle(estimate.theta - t->theta)});
  }
  FixTruthReport r;
  r.fixes = samples.size();
  if (samples.size() < 3) return r;
  const double n = static_cast<double>(samples.size());
  Eigen::Vector2d mean = Eigen::Vector2d::Zero(), centroid = Eigen::Vector2d::Zero();
  double mean_theta = 0.0;
  for (const Sample& s : samples) {
    mean += s.error / n;
    centroid += s.truth / n;
    mean_theta += s.heading_error / n;
  }
  Eigen::Vector3d variance = Eigen::Vector3d::Zero();
  double lag1 = 0.0;
  for (size_t i = 0; i < samples.size(); ++i) {
    const Eigen::Vector2d d = samples[i].error - mean;
    variance +=
        Eigen::Vector3d(d.x() * d.x(), d.y() * d.y(), std::pow(samples[i].heading_error - mean_theta, 2)) / n;
    if (i > 0) lag1 += d.dot(samples[i - 1].error - mean);
  }
  r.mean_x_m = mean.x();
  r.mean_y_m = mean.y();
  r.sigma_x_m = std::sqrt(variance.x());
  r.sigma_y_m = std::sqrt(variance.y());
  r.sigma_theta_rad = std::sqrt(variance.z());
  r.lag1_correlation = lag1 / (n - 1.0) / (variance.x() + variance.y());
  Eigen::Matrix4d normal = Eigen::Matrix4d::Zero();
  Eigen::Vector4d rhs = Eigen::Vector4d::Zero();
  for (const Sample& s : samples) {
    const Eigen::Vector2d q = s.truth - centroid;
    Eigen::Matrix<double, 2, 4> j;
    j << 1.0, 0.0, q.x(), -q.y(), 0.0, 1.0, q.y(), q.x();
    normal += j.transpose() * j;
    rhs += j.transpose() * s.error;
    r.half_extent_x_m = std::max(r.half_extent_x_m, std::abs(q.x()));
    r.half_extent_y_m = std::max(r.half_extent_y_m, std::abs(q.y()));
  }
  const Eigen::Vector4d fit = normal.ldlt().solve(rhs);
  r.expansion = fit[2];
  r.rotation_rad = fit[3];
  return r;
}

}  // namespace refloc
