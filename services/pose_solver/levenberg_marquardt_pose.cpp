#include "pose_solver/levenberg_marquardt_pose.hpp"

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

}  // namespace refloc
