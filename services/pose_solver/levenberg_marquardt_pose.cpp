#include "pose_solver/levenberg_marquardt_pose.hpp"

#include "common/laser_point_model.hpp"

#include <cmath>

namespace refloc {

void observation_residual_and_jacobian(const PointObservation& o, const Pose2& map_T_robot,
                                       const Pose2& robot_T_laser, Eigen::Vector2d& e,
                                       Eigen::Matrix<double, 2, 3>& j) {
  laser_point_residual_and_jacobian(o.map_p, o.laser_p, map_T_robot, robot_T_laser, e, j);
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
