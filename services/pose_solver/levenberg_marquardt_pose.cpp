#include "pose_solver/levenberg_marquardt_pose.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>

namespace refloc {

void observation_residual_and_jacobian(const PointObservation& o, const Pose2& map_T_robot,
                                       const Pose2& robot_T_laser, Eigen::Vector2d& e,
                                       Eigen::Matrix<double, 2, 3>& j) {
  const double c = std::cos(map_T_robot.theta), s = std::sin(map_T_robot.theta);
  Eigen::Matrix2d robot_R_map;
  robot_R_map << c, s, -s, c;
  Eigen::Matrix2d d_robot_R_map;  // derivative of robot_R_map w.r.t. theta
  d_robot_R_map << -s, c, -c, -s;
  const Eigen::Vector2d delta = o.map_p - map_T_robot.translation();
  const Eigen::Vector2d robot_p = robot_R_map * delta;
  const Eigen::Matrix2d laser_R_robot = robot_T_laser.rotation().transpose();
  const Eigen::Vector2d laser_p = laser_R_robot * (robot_p - robot_T_laser.translation());
  e = o.laser_p - laser_p;
  // e = z - h, so J = -dh/dpose.
  j.leftCols<2>() = laser_R_robot * robot_R_map;
  j.col(2) = -laser_R_robot * d_robot_R_map * delta;
}

Eigen::Vector2d predict_laser_point(const PointObservation& o, const Pose2& map_T_robot,
                                    const Pose2& robot_T_laser) {
  return (map_T_robot * robot_T_laser).inverse() * o.map_p;
}

double normalised_residual(const PointObservation& o, const Pose2& map_T_robot, const Pose2& robot_T_laser) {
  const Eigen::Vector2d e = o.laser_p - predict_laser_point(o, map_T_robot, robot_T_laser);
  return std::sqrt(std::max(0.0, e.dot(o.information * e)));
}

Eigen::Matrix3d pose_information(const std::vector<PointObservation>& observations,
                                 const std::vector<char>* use, const Pose2& map_T_robot,
                                 const Pose2& robot_T_laser) {
  Eigen::Matrix3d h = Eigen::Matrix3d::Zero();
  Eigen::Vector2d e;
  Eigen::Matrix<double, 2, 3> j;
  for (size_t i = 0; i < observations.size(); ++i) {
    if (use && !(*use)[i]) continue;
    observation_residual_and_jacobian(observations[i], map_T_robot, robot_T_laser, e, j);
    h += j.transpose() * observations[i].information * j;
  }
  return h;
}

LevenbergMarquardtResult refine_pose(const std::vector<PointObservation>& observations,
                                     const std::vector<char>* use, const Pose2& robot_T_laser,
                                     const Pose2& initial_map_T_robot, int max_iterations,
                                     double convergence_step) {
  LevenbergMarquardtResult result;
  result.map_T_robot = initial_map_T_robot;
  Eigen::Vector2d e;
  Eigen::Matrix<double, 2, 3> j;
  const auto evaluate = [&](const Pose2& pose, Eigen::Matrix3d* h, Eigen::Vector3d* g) {
    double cost = 0.0;
    if (h) h->setZero();
    if (g) g->setZero();
    for (size_t i = 0; i < observations.size(); ++i) {
      if (use && !(*use)[i]) continue;
      observation_residual_and_jacobian(observations[i], pose, robot_T_laser, e, j);
      const Eigen::Vector2d we = observations[i].information * e;
      cost += e.dot(we);
      if (h) *h += j.transpose() * observations[i].information * j;
      if (g) *g += j.transpose() * we;
    }
    return cost;
  };

  Eigen::Matrix3d h;
  Eigen::Vector3d g;
  double cost = evaluate(result.map_T_robot, &h, &g);
  double lambda = 1e-6;  // starts as Gauss-Newton; grows only when a step fails to reduce the cost
  for (int it = 0; it < max_iterations; ++it) {
    result.iterations = it + 1;
    Eigen::Matrix3d damped = h;
    damped.diagonal() *= 1.0 + lambda;
    // e = z - h(x) and J = -dh/dx: the Gauss-Newton step is -(J^T W J)^-1 J^T W e.
    const Eigen::Vector3d step = -damped.ldlt().solve(g);
    if (!step.allFinite()) return result;
    const Pose2 candidate{result.map_T_robot.x + step(0), result.map_T_robot.y + step(1),
                          wrap_angle(result.map_T_robot.theta + step(2))};
    const double candidate_cost = evaluate(candidate, nullptr, nullptr);
    if (candidate_cost <= cost) {
      result.map_T_robot = candidate;
      cost = evaluate(candidate, &h, &g);
      lambda = std::max(1e-9, lambda * 0.1);
      if (step.norm() < convergence_step) {
        result.converged = true;
        break;
      }
    } else {
      lambda *= 10.0;
      if (lambda > 1e8) {
        // No descent direction left: we are at the minimum to numerical precision.
        result.converged = true;
        break;
      }
    }
  }
  if (!result.converged && result.iterations >= max_iterations) {
    // A step still shrinking at the limit is as good as converged when it is tiny.
    result.converged = g.norm() < 1e-6 * (1.0 + cost);
  }
  result.cost = cost;
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(h);
  if (!lu.isInvertible()) {
    result.converged = false;
    return result;
  }
  result.covariance = lu.inverse();
  return result;
}

}  // namespace refloc
