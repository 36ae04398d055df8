#include "pose_solver/pose_solver.hpp"

#include "pose_solver/levenberg_marquardt_pose.hpp"
#include "pose_solver/paper_trilateration.hpp"
#include "pose_solver/range_bias_refinement.hpp"

#include <Eigen/LU>

#include <cmath>

namespace refloc {

PoseSolver::PoseSolver(const SolverConfig& config, const Pose2& robot_T_laser)
    : config_(config),
      robot_T_laser_(robot_T_laser),
      range_bias_prior_{config.range_bias.prior_mean, config.range_bias.prior_sigma,
                        config.range_bias.estimate} {}

void PoseSolver::solve(const std::vector<ReflectorDetection>& detections,
                       const std::vector<ReflectorMatch>& matches, PoseSolution& solution) {
  solution.status = SolveStatus::kLost;
  solution.reflectors_used = 0;
  solution.rms_residual = 0.0;
  solution.iterations = 0;
  solution.covariance = Eigen::Matrix3d::Identity();
  solution.used.assign(matches.size(), 0);
  solution.range_bias_use = RangeBiasUse::kNoSolution;
  solution.range_bias = 0.0;
  solution.range_bias_sigma = 0.0;
  solution.range_bias_scan_sigma = 0.0;
  observations_.clear();
  observation_match_.clear();
  // make_observations skips bad indices; keep track of which match each observation is.
  for (size_t m = 0; m < matches.size(); ++m) {
    const int d = matches[m].detection_index;
    if (d >= 0 && d < static_cast<int>(detections.size())) observation_match_.push_back(static_cast<int>(m));
  }
  make_observations(detections, matches, config_.detection_min_sigma, observations_);
  use_.assign(observations_.size(), 1);
  if (observations_.size() < 3) return;
  if (config_.mode == SolverMode::kPaper) {
    solve_paper(solution);
  } else {
    solve_default(solution);
  }
}

void PoseSolver::solve_paper(PoseSolution& solution) {
  // The paper's method as published: it knows no range offset.
  corrected_ = observations_;
  Eigen::Vector2d map_p_laser;
  if (!trilaterate_position(observations_, nullptr, config_.min_position_conditioning, map_p_laser)) return;
  const double laser_heading = paper_mean_heading(observations_, map_p_laser);
  // The paper's laser axis is the robot's axis; a mount rotation is taken off here.
  const double robot_heading = wrap_angle(laser_heading - robot_T_laser_.theta);
  const Eigen::Vector2d map_p_robot = paper_robot_position(map_p_laser, robot_heading, robot_T_laser_);
  solution.map_T_robot = Pose2{map_p_robot.x(), map_p_robot.y(), robot_heading};
  // The paper gives no covariance; the linearised one at its solution lets fusion weigh it.
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(
      pose_information(observations_, nullptr, solution.map_T_robot, robot_T_laser_));
  if (lu.isInvertible()) solution.covariance = lu.inverse();
  finish(solution);
}

void PoseSolver::solve_default(PoseSolution& solution) {
  const RangeBiasPrior& prior = range_bias_prior_;
  remove_range_bias(observations_, prior.mean, corrected_);
  Eigen::Vector2d map_p_laser;
  if (!trilaterate_position(corrected_, nullptr, config_.min_position_conditioning, map_p_laser)) return;
  const double laser_heading = circular_mean_heading(corrected_, nullptr, map_p_laser);
  const Pose2 map_T_laser{map_p_laser.x(), map_p_laser.y(), laser_heading};
  solve_biased(map_T_laser * robot_T_laser_.inverse(), solution);
}

bool PoseSolver::solve_biased(Pose2 estimate, PoseSolution& solution) {
  const RangeBiasPrior& prior = range_bias_prior_;
  RangeBiasPrior held = prior;
  held.estimate = false;
  const bool joint = prior.estimate && prior.sigma > 0.0;
  int remaining = static_cast<int>(observations_.size());
  BiasedPoseResult r;
  while (true) {
    r = refine_pose_and_range_bias(observations_, &use_, robot_T_laser_, estimate, joint ? prior : held,
                                   config_.max_iterations, config_.convergence_step);
    solution.iterations += r.iterations;
    if (!r.converged) return false;
    estimate = r.map_T_robot;
    remove_range_bias(observations_, r.range_bias, corrected_);
    // Drop the worst match while it is an outlier and at least three remain.
    double worst = 0.0;
    size_t worst_index = 0;
    for (size_t i = 0; i < corrected_.size(); ++i) {
      if (!use_[i]) continue;
      const double n = normalised_residual(corrected_[i], estimate, robot_T_laser_);
      if (n > worst) {
        worst = n;
        worst_index = i;
      }
    }
    if (worst <= config_.outlier_threshold || remaining <= 3) break;
    use_[worst_index] = 0;
    --remaining;
  }
  // The geometric test: enough reflectors, and this scan alone tells b from a translation.
  solution.range_bias_scan_sigma = range_bias_scan_sigma(r.data_information);
  RangeBiasUse use = RangeBiasUse::kEstimated;
  if (!joint) {
    use = RangeBiasUse::kNotEstimating;
  } else if (remaining < config_.range_bias.min_reflectors) {
    use = RangeBiasUse::kFewReflectors;
  } else if (!(solution.range_bias_scan_sigma <= config_.range_bias.max_scan_sigma)) {
    use = RangeBiasUse::kWeakGeometry;
  }
  Eigen::Matrix3d covariance;
  double bias_sigma = prior.sigma;
  if (use == RangeBiasUse::kEstimated) {
    if (!pose_covariance_bias_estimated(r.data_information, prior.sigma, covariance, bias_sigma))
      return false;
  } else {
    if (joint) {
      // b cannot be told from the pose here: the pose with b held at its prior, not the joint guess.
      r = refine_pose_and_range_bias(observations_, &use_, robot_T_laser_, estimate, held,
                                     config_.max_iterations, config_.convergence_step);
      solution.iterations += r.iterations;
      if (!r.converged) return false;
      remove_range_bias(observations_, r.range_bias, corrected_);
    }
    if (!pose_covariance_bias_fixed(r.data_information, prior.sigma, covariance)) return false;
  }
  solution.map_T_robot = r.map_T_robot;
  solution.covariance = covariance;
  solution.range_bias_use = use;
  solution.range_bias = r.range_bias;
  solution.range_bias_sigma = bias_sigma;
  finish(solution);
  return true;
}

void PoseSolver::finish(PoseSolution& solution) const {
  double sum2 = 0.0;
  int used = 0;
  bool outlier_left = false;
  for (size_t i = 0; i < corrected_.size(); ++i) {
    if (!use_[i]) continue;
    ++used;
    solution.used[static_cast<size_t>(observation_match_[i])] = 1;
    const Eigen::Vector2d predicted =
        predict_laser_point(corrected_[i], solution.map_T_robot, robot_T_laser_);
    const double range_error = corrected_[i].range - predicted.norm();
    sum2 += range_error * range_error;
    outlier_left = outlier_left || normalised_residual(corrected_[i], solution.map_T_robot, robot_T_laser_) >
                                       config_.outlier_threshold;
  }
  solution.reflectors_used = used;
  solution.rms_residual = used > 0 ? std::sqrt(sum2 / used) : 0.0;
  if (!solution.covariance.allFinite() || used < 3) {
    solution.status = SolveStatus::kLost;
  } else if (used < config_.min_reflectors_ok || solution.rms_residual > config_.max_rms_residual_ok ||
             outlier_left) {
    solution.status = SolveStatus::kDegraded;
  } else {
    solution.status = SolveStatus::kOk;
  }
}

}  // namespace refloc
