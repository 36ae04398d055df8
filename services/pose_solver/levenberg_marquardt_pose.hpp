#pragma once
// Joint Levenberg-Marquardt refinement of map_T_robot from detections of known
// reflectors: residual e_i = laser_p_i - laser_T_robot robot_T_map map_p_i,
// weighted by the detection's information matrix; covariance (J^T W J)^-1.

#include "pose_solver/point_observation.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

struct LevenbergMarquardtResult {
  bool converged = false;
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< (J^T W J)^-1 at the solution
  double cost = 0.0;                                         ///< sum of e^T W e over the observations used
  int iterations = 0;
};

/// Refine map_T_robot from initial using the observations with use[i] != 0 (all if use is null).
LevenbergMarquardtResult refine_pose(const std::vector<PointObservation>& observations,
                                     const std::vector<char>* use, const Pose2& robot_T_laser,
                                     const Pose2& initial_map_T_robot, int max_iterations,
                                     double convergence_step);

/// Residual e = laser_p - predicted and its Jacobian de/d(x, y, theta) of map_T_robot.
void observation_residual_and_jacobian(const PointObservation& o, const Pose2& map_T_robot,
                                       const Pose2& robot_T_laser, Eigen::Vector2d& e,
                                       Eigen::Matrix<double, 2, 3>& j);

/// Normalised residual sqrt(e^T W e) of one observation at map_T_robot.
double normalised_residual(const PointObservation& o, const Pose2& map_T_robot, const Pose2& robot_T_laser);

/// Predicted centre of o's reflector in the laser frame at map_T_robot [m].
Eigen::Vector2d predict_laser_point(const PointObservation& o, const Pose2& map_T_robot,
                                    const Pose2& robot_T_laser);

/// (J^T W J) at map_T_robot: the information of the observations used about (x, y, theta).
Eigen::Matrix3d pose_information(const std::vector<PointObservation>& observations,
                                 const std::vector<char>* use, const Pose2& map_T_robot,
                                 const Pose2& robot_T_laser);

}  // namespace refloc
