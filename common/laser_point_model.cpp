#include "common/laser_point_model.hpp"

#include <cmath>

namespace refloc {

void laser_point_residual_and_jacobian(const Eigen::Vector2d& map_p, const Eigen::Vector2d& laser_p,
                                       const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                       Eigen::Vector2d& e, Eigen::Matrix<double, 2, 3>& j) {
  const double c = std::cos(map_T_robot.theta), s = std::sin(map_T_robot.theta);
  Eigen::Matrix2d robot_R_map;
  robot_R_map << c, s, -s, c;
  Eigen::Matrix2d d_robot_R_map;  // derivative of robot_R_map w.r.t. theta
  d_robot_R_map << -s, c, -c, -s;
  const Eigen::Vector2d delta = map_p - map_T_robot.translation();
  const Eigen::Vector2d robot_p = robot_R_map * delta;
  const Eigen::Matrix2d laser_R_robot = robot_T_laser.rotation().transpose();
  e = laser_p - laser_R_robot * (robot_p - robot_T_laser.translation());
  // e = z - h, so J = -dh/dpose.
  j.leftCols<2>() = laser_R_robot * robot_R_map;
  j.col(2) = -laser_R_robot * d_robot_R_map * delta;
}

}  // namespace refloc
