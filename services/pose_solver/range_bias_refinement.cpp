#include "pose_solver/range_bias_refinement.hpp"

#include "pose_solver/levenberg_marquardt_pose.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace refloc {
namespace {

Eigen::Vector2d beam_direction(const PointObservation& o) {
  const double r = o.laser_p.norm();
  return r > 0.0 ? Eigen::Vector2d(o.laser_p / r) : Eigen::Vector2d::Zero();
}

}  // namespace

BiasedPoseResult refine_pose_and_range_bias(const std::vector<PointObservation>& observations,
                                            const std::vector<char>* use, const Pose2& robot_T_laser,
                                            const Pose2& initial_map_T_robot, const RangeBiasPrior& prior,
                                            int max_iterations, double convergence_step) {
  BiasedPoseResult result;
  result.map_T_robot = initial_map_T_robot;
  result.range_bias = prior.mean;
  const bool estimate = prior.estimate && prior.sigma > 0.0;
  const double prior_weight = estimate ? 1.0 / (prior.sigma * prior.sigma) : 0.0;
  Eigen::Vector2d e;
  Eigen::Matrix<double, 2, 3> j3;
  Eigen::Matrix<double, 2, 4> j;
  // Cost, data-only information and gradient (with the prior) over (x, y, theta, b).
  const auto evaluate = [&](const Pose2& pose, double bias, Eigen::Matrix4d* h, Eigen::Vector4d* g) {
    double cost = 0.0;
    if (h) h->setZero();
    if (g) g->setZero();
    for (size_t i = 0; i < observations.size(); ++i) {
      if (use && !(*use)[i]) continue;
      const PointObservation& o = observations[i];
      observation_residual_and_jacobian(o, pose, robot_T_laser, e, j3);
      const Eigen::Vector2d u = beam_direction(o);
      e -= bias * u;
      j.leftCols<3>() = j3;
      j.col(3) = -u;
      const Eigen::Vector2d we = o.information * e;
      cost += e.dot(we);
      if (h) *h += j.transpose() * o.information * j;
      if (g) *g += j.transpose() * we;
    }
    const double d = bias - prior.mean;
    cost += prior_weight * d * d;
    if (g) (*g)(3) += prior_weight * d;
    return cost;
  };

  Eigen::Matrix4d h;
  Eigen::Vector4d g;
  double cost = evaluate(result.map_T_robot, result.range_bias, &h, &g);
  double lambda = 1e-6;  // Gauss-Newton first; grows only when a step fails to reduce the cost
  for (int it = 0; it < max_iterations; ++it) {
    result.iterations = it + 1;
    Eigen::Vector4d step = Eigen::Vector4d::Zero();
    if (estimate) {
      Eigen::Matrix4d damped = h;
      damped(3, 3) += prior_weight;
      damped.diagonal() *= 1.0 + lambda;
      step = -damped.ldlt().solve(g);
    } else {
      Eigen::Matrix3d damped = h.topLeftCorner<3, 3>();
      damped.diagonal() *= 1.0 + lambda;
      step.head<3>() = -damped.ldlt().solve(g.head<3>());
    }
    if (!step.allFinite()) return result;
    const Pose2 candidate{result.map_T_robot.x + step(0), result.map_T_robot.y + step(1),
                          wrap_angle(result.map_T_robot.theta + step(2))};
    const double candidate_bias = result.range_bias + step(3);
    const double candidate_cost = evaluate(candidate, candidate_bias, nullptr, nullptr);
    if (candidate_cost <= cost) {
      result.map_T_robot = candidate;
      result.range_bias = candidate_bias;
      cost = evaluate(candidate, candidate_bias, &h, &g);
      lambda = std::max(1e-9, lambda * 0.1);
      if (step.norm() < convergence_step) {
        result.converged = true;
        break;
      }
    } else {
      lambda *= 10.0;
      if (lambda > 1e8) {
        result.converged = true;  // no descent left: at the minimum to numerical precision
        break;
      }
    }
  }
  const double gradient = estimate ? g.norm() : g.head<3>().norm();
  if (!result.converged && result.iterations >= max_iterations)
    result.converged = gradient < 1e-6 * (1.0 + cost);
  result.cost = cost;
  result.data_information = h;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(h.topLeftCorner<3, 3>());
  if (!lu.isInvertible()) result.converged = false;
  return result;
}

double range_bias_scan_sigma(const Eigen::Matrix4d& data_information) {
  const Eigen::Matrix3d hpp = data_information.topLeftCorner<3, 3>();
  const Eigen::Vector3d hpb = data_information.topRightCorner<3, 1>();
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(hpp);
  if (!lu.isInvertible()) return std::numeric_limits<double>::infinity();
  const double schur = data_information(3, 3) - hpb.dot(lu.solve(hpb));
  // Relative to H_bb: below 1e-9 of it b is a pose direction to rounding error.
  if (!(schur > 1e-9 * data_information(3, 3))) return std::numeric_limits<double>::infinity();
  return 1.0 / std::sqrt(schur);
}

bool pose_covariance_bias_estimated(const Eigen::Matrix4d& data_information, double prior_sigma,
                                    Eigen::Matrix3d& covariance, double& bias_sigma) {
  Eigen::Matrix4d h = data_information;
  if (prior_sigma > 0.0) h(3, 3) += 1.0 / (prior_sigma * prior_sigma);
  const Eigen::FullPivLU<Eigen::Matrix4d> lu(h);
  if (!lu.isInvertible()) return false;
  const Eigen::Matrix4d joint = lu.inverse();
  covariance = joint.topLeftCorner<3, 3>();
  bias_sigma = std::sqrt(std::max(0.0, joint(3, 3)));
  return covariance.allFinite() && std::isfinite(bias_sigma);
}

bool pose_covariance_bias_fixed(const Eigen::Matrix4d& data_information, double bias_sigma,
                                Eigen::Matrix3d& covariance) {
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(data_information.topLeftCorner<3, 3>());
  if (!lu.isInvertible()) return false;
  covariance = lu.inverse();
  const Eigen::Vector3d pose_per_bias = -covariance * data_information.topRightCorner<3, 1>();
  covariance += (bias_sigma * bias_sigma) * pose_per_bias * pose_per_bias.transpose();
  return covariance.allFinite();
}

void remove_range_bias(const std::vector<PointObservation>& in, double bias,
                       std::vector<PointObservation>& out) {
  out = in;
  for (PointObservation& o : out) {
    o.laser_p -= bias * beam_direction(o);
    o.range -= bias;
  }
}

}  // namespace refloc
