#pragma once
// The one observation model of a matched reflector: its centre in the laser frame as seen from
// map_T_robot through the mount robot_T_laser, the residual e = measured - predicted, and
// de/d(x, y, theta) of map_T_robot. pose_solver's refinement and pose_fusion's detection update
// both use it, so the single-scan fix and the fused pose cannot disagree about the geometry.

#include "common/se2.hpp"

#include <Eigen/Core>

namespace refloc {

/// e = laser_p - laser_T_map * map_p; j = de / d(x, y, theta) (= -dh/dpose).
void laser_point_residual_and_jacobian(const Eigen::Vector2d& map_p, const Eigen::Vector2d& laser_p,
                                       const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                       Eigen::Vector2d& e, Eigen::Matrix<double, 2, 3>& j);

}  // namespace refloc
