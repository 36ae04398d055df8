#include "common/covariance_propagation.hpp"

#include <cmath>

namespace refloc {

Eigen::Matrix3d compose_jacobian_lhs(const Pose2& a, const Pose2& b) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 2) = -s * b.x - c * b.y;
  j(1, 2) = c * b.x - s * b.y;
  return j;
}

Eigen::Matrix3d compose_jacobian_rhs(const Pose2& a) {
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  Eigen::Matrix3d j = Eigen::Matrix3d::Identity();
  j(0, 0) = c;
  j(0, 1) = -s;
  j(1, 0) = s;
  j(1, 1) = c;
  return j;
}

Eigen::Matrix3d compose_covariance(const Pose2& a, const Eigen::Matrix3d& p_a, const Pose2& b,
                                   const Eigen::Matrix3d& q_b) {
  const Eigen::Matrix3d f = compose_jacobian_lhs(a, b);
  const Eigen::Matrix3d g = compose_jacobian_rhs(a);
  return f * p_a * f.transpose() + g * q_b * g.transpose();
}

Eigen::Matrix3d propagate_through_mount(const Pose2& parent_T_robot, const Eigen::Matrix3d& robot_covariance,
                                        const Pose2& robot_T_sensor) {
  const Eigen::Matrix3d j = compose_jacobian_lhs(parent_T_robot, robot_T_sensor);
  return j * robot_covariance * j.transpose();
}

}  // namespace refloc
