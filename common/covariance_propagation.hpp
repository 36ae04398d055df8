#pragma once
// First-order covariance propagation through SE(2) composition c = a * b, in the
// (x, y, theta) parameterization of Pose2 with b's uncertainty in a's body frame.
// One Jacobian, used by odometry integration, the fusion EKF's prediction and the
// matcher's map_T_laser prior (the mount lever arm).

#include "common/se2.hpp"

#include <Eigen/Core>

namespace refloc {

/// d(a * b) / da: heading error of a swings b's translation (the lever arm).
Eigen::Matrix3d compose_jacobian_lhs(const Pose2& a, const Pose2& b);

/// d(a * b) / db: b's body-frame error rotated into a's parent frame.
Eigen::Matrix3d compose_jacobian_rhs(const Pose2& a);

/// Covariance of a * b for independent a (covariance p_a) and b (covariance q_b,
/// in a's body frame) [m^2, m rad, rad^2].
Eigen::Matrix3d compose_covariance(const Pose2& a, const Eigen::Matrix3d& p_a, const Pose2& b,
                                   const Eigen::Matrix3d& q_b);

/// Covariance of parent_T_robot * robot_T_sensor for an exactly known mount: the
/// robot pose covariance seen at the sensor (heading error becomes position error
/// through the lever arm) [m^2, m rad, rad^2].
Eigen::Matrix3d propagate_through_mount(const Pose2& parent_T_robot, const Eigen::Matrix3d& robot_covariance,
                                        const Pose2& robot_T_sensor);

}  // namespace refloc
