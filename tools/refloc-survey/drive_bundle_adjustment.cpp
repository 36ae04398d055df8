#include "drive_bundle_adjustment.hpp"

#include "drive_bundle_residuals.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <memory>

namespace refloc {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

class Bundle {
 public:
  Bundle(const BundleProblem& p, const BundleOptions& o) : p_(p), o_(o) {
    poses_.reserve(p.map_T_robot.size());
    for (const Pose2& x : p.map_T_robot) poses_.push_back({x.x, x.y, x.theta});
    landmarks_.reserve(p.map_p_landmark.size());
    for (const Eigen::Vector2d& m : p.map_p_landmark) landmarks_.push_back({m.x(), m.y()});
    for (const BundleAnchor& a : p.anchors)
      landmarks_[static_cast<size_t>(a.landmark)] = {a.map_p.x(), a.map_p.y()};
  }

  void build() {
    const std::vector<double> weights = same_view_weights();
    for (size_t i = 0; i < p_.observations.size(); ++i) {
      const BundleObservation& z = p_.observations[i];
      auto* f =
          new ceres::AutoDiffCostFunction<PointResidual, 2, 3, 2, 1>(new PointResidual(point_residual(z)));
      ceres::LossFunction* loss = new ceres::HuberLoss(o_.huber_scale);
      if (weights[i] < 1.0) loss = new ceres::ScaledLoss(loss, weights[i], ceres::TAKE_OWNERSHIP);
      problem_.AddResidualBlock(f, loss, pose(z.pose), landmark(z.landmark), &bias_);
    }
    for (size_t k = 1; k < poses_.size(); ++k) {
      const Pose2 measured = p_.odom_T_robot[k - 1].inverse() * p_.odom_T_robot[k];
      Eigen::Matrix3d covariance = increment_covariance(measured, p_.odometry_noise);
      covariance.diagonal() += Eigen::Vector3d(o_.odometry_min_sigma_m * o_.odometry_min_sigma_m,
                                               o_.odometry_min_sigma_m * o_.odometry_min_sigma_m,
                                               o_.odometry_min_sigma_rad * o_.odometry_min_sigma_rad);
      auto* f = new ceres::AutoDiffCostFunction<OdometryResidual, 3, 3, 3>(
          new OdometryResidual{measured, whitening_of<3>(covariance)});
      problem_.AddResidualBlock(f, nullptr, poses_[k - 1].data(), poses_[k].data());
    }
    if (problem_.HasParameterBlock(&bias_) && !o_.estimate_range_bias)
      problem_.SetParameterBlockConstant(&bias_);
    if (p_.anchors.empty()) {
      if (!poses_.empty() && problem_.HasParameterBlock(poses_.front().data()))
        problem_.SetParameterBlockConstant(poses_.front().data());
    } else {
      for (const BundleAnchor& a : p_.anchors)
        if (problem_.HasParameterBlock(landmark(a.landmark)))
          problem_.SetParameterBlockConstant(landmark(a.landmark));
    }
  }

  BundleResult solve() {
    BundleResult r;
    ceres::Solver::Options options;
    options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    options.max_num_iterations = o_.max_iterations;
    options.num_threads = o_.threads;
    options.function_tolerance = 1e-10;
    options.parameter_tolerance = 1e-10;
    ceres::Solver::Summary summary;
    const auto start = std::chrono::steady_clock::now();
    ceres::Solve(options, &problem_, &summary);
    r.solve_s = seconds_since(start);
    r.message = summary.BriefReport();
    r.iterations = static_cast<int>(summary.iterations.size());
    r.ok = summary.IsSolutionUsable();
    if (!r.ok) return r;
    ceres::Problem::EvaluateOptions plain;
    plain.apply_loss_function = false;
    double cost = 0.0;
    problem_.Evaluate(plain, &cost, nullptr, nullptr, nullptr);
    const int dof = summary.num_residuals_reduced - summary.num_effective_parameters_reduced;
    r.chi2_per_dof = dof > 0 ? 2.0 * cost / dof : 0.0;
    r.range_bias = bias_;
    for (const auto& x : poses_) r.map_T_robot.push_back({x[0], x[1], x[2]});
    landmark_statistics(r);
    if (o_.compute_covariance) covariance(r);
    return r;
  }

 private:
  double* pose(int i) { return poses_[static_cast<size_t>(i)].data(); }
  double* landmark(int i) { return landmarks_[static_cast<size_t>(i)].data(); }

  /// Per observation, 1 / (detections in its run of the same view of its landmark): see
  /// BundleOptions::same_view_beam_steps. Views are predicted from the initial poses and
  /// landmarks, not from the measurements, whose noise would split a standstill into runs.
  std::vector<double> same_view_weights() const {
    std::vector<double> weights(p_.observations.size(), 1.0);
    const double same_bearing = o_.same_view_beam_steps * p_.angle_increment;
    if (same_bearing <= 0.0) return weights;
    std::vector<size_t> order(p_.observations.size());
    for (size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
      const BundleObservation &za = p_.observations[a], &zb = p_.observations[b];
      return za.landmark != zb.landmark ? za.landmark < zb.landmark : za.pose < zb.pose;
    });
    size_t run_begin = 0;
    double run_bearing = 0.0, run_range = 0.0;
    const auto close_run = [&](size_t end) {
      for (size_t k = run_begin; k < end; ++k) weights[order[k]] = 1.0 / static_cast<double>(end - run_begin);
    };
    for (size_t k = 0; k < order.size(); ++k) {
      const BundleObservation& z = p_.observations[order[k]];
      const Pose2 map_T_laser = p_.map_T_robot[static_cast<size_t>(z.pose)] * p_.robot_T_laser;
      const Eigen::Vector2d laser_p =
          map_T_laser.inverse() * p_.map_p_landmark[static_cast<size_t>(z.landmark)];
      const double bearing = std::atan2(laser_p.y(), laser_p.x()), range = laser_p.norm();
      const bool same_run = k > run_begin && p_.observations[order[run_begin]].landmark == z.landmark &&
                            std::abs(std::remainder(bearing - run_bearing, 2.0 * M_PI)) < same_bearing &&
                            std::abs(range - run_range) < o_.same_view_range_m;
      if (!same_run) {
        close_run(k);
        run_begin = k;
        run_bearing = bearing;
        run_range = range;
      }
    }
    close_run(order.size());
    return weights;
  }

  PointResidual point_residual(const BundleObservation& z) const {
    Eigen::Matrix2d covariance = z.covariance;
    covariance.diagonal().array() += o_.detection_min_sigma * o_.detection_min_sigma;
    return {z.laser_p, z.laser_p.normalized(), whitening_of<2>(covariance), p_.robot_T_laser};
  }

  void landmark_statistics(BundleResult& r) const {
    r.landmarks.resize(landmarks_.size());
    std::vector<double> sum_e2(landmarks_.size(), 0.0), sum_n2(landmarks_.size(), 0.0);
    for (const BundleObservation& z : p_.observations) {
      const auto j = static_cast<size_t>(z.landmark);
      const PointResidual f = point_residual(z);
      double e[2], n[2];
      f.error(poses_[static_cast<size_t>(z.pose)].data(), landmarks_[j].data(), &bias_, e);
      f(poses_[static_cast<size_t>(z.pose)].data(), landmarks_[j].data(), &bias_, n);
      r.residuals.emplace_back(e[0], e[1]);
      const double n2 = n[0] * n[0] + n[1] * n[1];
      sum_e2[j] += e[0] * e[0] + e[1] * e[1];
      sum_n2[j] += n2;
      ++r.landmarks[j].observations;
      if (n2 > o_.huber_scale * o_.huber_scale) ++r.landmarks[j].outliers;
    }
    for (size_t j = 0; j < landmarks_.size(); ++j) {
      BundleLandmark& l = r.landmarks[j];
      l.map_p = {landmarks_[j][0], landmarks_[j][1]};
      if (l.observations == 0) continue;
      l.residual_rms = std::sqrt(sum_e2[j] / l.observations);
      l.normalised_rms = std::sqrt(sum_n2[j] / l.observations);
    }
  }

  void covariance(BundleResult& r) {
    const auto start = std::chrono::steady_clock::now();
    ceres::Covariance::Options options;
    options.num_threads = o_.threads;
    ceres::Covariance covariance(options);
    std::vector<size_t> free;
    for (size_t j = 0; j < landmarks_.size(); ++j)
      if (problem_.HasParameterBlock(landmarks_[j].data()) &&
          !problem_.IsParameterBlockConstant(landmarks_[j].data()))
        free.push_back(j);
    // The frame-free covariances need every pair of landmarks' blocks: a bounded number of them.
    const bool joint = p_.anchors.empty() && free.size() >= 3 && free.size() <= kMaxJointLandmarks;
    std::vector<std::pair<const double*, const double*>> blocks;
    for (size_t a = 0; a < free.size(); ++a)
      for (size_t b = a; b < (joint ? free.size() : a + 1); ++b)
        blocks.emplace_back(landmarks_[free[a]].data(), landmarks_[free[b]].data());
    const bool bias_free = problem_.HasParameterBlock(&bias_) && !problem_.IsParameterBlockConstant(&bias_);
    if (bias_free) blocks.emplace_back(&bias_, &bias_);
    if (!covariance.Compute(blocks, &problem_)) {
      r.message += "; covariance not computable (rank deficient: a landmark or the frame is unobserved)";
      r.covariance_s = seconds_since(start);
      return;
    }
    for (size_t j = 0; j < landmarks_.size(); ++j) {
      if (!problem_.HasParameterBlock(landmarks_[j].data()) ||
          problem_.IsParameterBlockConstant(landmarks_[j].data()))
        continue;
      double c[4];
      covariance.GetCovarianceBlock(landmarks_[j].data(), landmarks_[j].data(), c);
      r.landmarks[j].covariance << c[0], c[1], c[2], c[3];
    }
    if (bias_free) {
      double c = 0.0;
      covariance.GetCovarianceBlock(&bias_, &bias_, &c);
      r.range_bias_sigma = std::sqrt(std::max(0.0, c));
    }
    if (joint) frame_free_covariances(covariance, free, r);
    r.covariance_s = seconds_since(start);
  }

  /// The landmarks' joint covariance projected onto what a rigid motion of the whole map cannot
  /// change: P S P with P = I - J (J^T J)^-1 J^T, J the landmarks' motion under a translation and
  /// a turn about their centroid (the unweighted rigid alignment `compare` makes).
  void frame_free_covariances(const ceres::Covariance& covariance, const std::vector<size_t>& free,
                              BundleResult& r) const {
    const auto n = static_cast<Eigen::Index>(free.size());
    Eigen::MatrixXd joint(2 * n, 2 * n);
    for (Eigen::Index a = 0; a < n; ++a)
      for (Eigen::Index b = a; b < n; ++b) {
        double c[4];
        covariance.GetCovarianceBlock(landmarks_[free[static_cast<size_t>(a)]].data(),
                                      landmarks_[free[static_cast<size_t>(b)]].data(), c);
        const Eigen::Matrix2d block = Eigen::Map<const Eigen::Matrix<double, 2, 2, Eigen::RowMajor>>(c);
        joint.block<2, 2>(2 * a, 2 * b) = block;
        joint.block<2, 2>(2 * b, 2 * a) = block.transpose();
      }
    Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
    for (size_t j : free) centroid += Eigen::Vector2d(landmarks_[j][0], landmarks_[j][1]);
    centroid /= static_cast<double>(n);
    Eigen::MatrixXd motion(2 * n, 3);
    for (Eigen::Index a = 0; a < n; ++a) {
      const auto& l = landmarks_[free[static_cast<size_t>(a)]];
      motion.block<2, 3>(2 * a, 0) << 1.0, 0.0, -(l[1] - centroid.y()), 0.0, 1.0, l[0] - centroid.x();
    }
    const Eigen::MatrixXd projection =
        Eigen::MatrixXd::Identity(2 * n, 2 * n) -
        motion * (motion.transpose() * motion).ldlt().solve(motion.transpose());
    const Eigen::MatrixXd frame_free = projection * joint * projection.transpose();
    for (Eigen::Index a = 0; a < n; ++a)
      r.landmarks[free[static_cast<size_t>(a)]].frame_free_covariance = frame_free.block<2, 2>(2 * a, 2 * a);
  }

  static constexpr size_t kMaxJointLandmarks = 200;

  const BundleProblem& p_;
  BundleOptions o_;
  std::vector<std::array<double, 3>> poses_;
  std::vector<std::array<double, 2>> landmarks_;
  double bias_ = 0.0;
  ceres::Problem problem_;
};

}  // namespace

BundleResult adjust_bundle(const BundleProblem& problem, const BundleOptions& options) {
  Bundle bundle(problem, options);
  bundle.build();
  return bundle.solve();
}

}  // namespace refloc
