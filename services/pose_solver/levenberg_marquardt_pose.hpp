#pragma once
// The observation model of the Levenberg-Marquardt pose refinement: residual
// e_i = laser_p_i - laser_T_robot robot_T_map map_p_i of one detection of a known reflector,
// weighted by the detection's information matrix, and its Jacobian. The one LM loop over it
// (with or without the range bias) is refine_pose_and_range_bias (range_bias_refinement.hpp).

#include "pose_solver/point_observation.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

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
