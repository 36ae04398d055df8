#include "pose_solver/crlb.hpp"

#include <Eigen/LU>

#include <cmath>

namespace refloc {

Eigen::Matrix3d pose_fisher_information(const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                        const std::vector<Eigen::Vector2d>& map_p_reflectors,
                                        const RangeBearingNoise& noise) {
  const double c = std::cos(map_T_robot.theta), s = std::sin(map_T_robot.theta);
  Eigen::Matrix2d robot_R_map, d_robot_R_map;
  robot_R_map << c, s, -s, c;
  d_robot_R_map << -s, c, -c, -s;
  const Eigen::Matrix2d laser_R_robot = robot_T_laser.rotation().transpose();
  const Eigen::Vector2d weights(1.0 / (noise.range_sigma * noise.range_sigma),
                                1.0 / (noise.bearing_sigma * noise.bearing_sigma));
  Eigen::Matrix3d fisher = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector2d& map_p : map_p_reflectors) {
    const Eigen::Vector2d delta = map_p - map_T_robot.translation();
    const Eigen::Vector2d laser_p = laser_R_robot * (robot_R_map * delta - robot_T_laser.translation());
    const double r2 = laser_p.squaredNorm();
    if (r2 <= 0.0) continue;
    const double r = std::sqrt(r2);
    // d(laser_p)/d(x, y, theta), then d(range, bearing)/d(laser_p).
    Eigen::Matrix<double, 2, 3> dp;
    dp.leftCols<2>() = -laser_R_robot * robot_R_map;
    dp.col(2) = laser_R_robot * d_robot_R_map * delta;
    Eigen::Matrix2d polar;
    polar << laser_p.x() / r, laser_p.y() / r, -laser_p.y() / r2, laser_p.x() / r2;
    const Eigen::Matrix<double, 2, 3> j = polar * dp;
    fisher += j.transpose() * weights.asDiagonal() * j;
  }
  return fisher;
}

std::optional<Eigen::Matrix3d> pose_crlb(const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                         const std::vector<Eigen::Vector2d>& map_p_reflectors,
                                         const RangeBearingNoise& noise) {
  const Eigen::Matrix3d fisher = pose_fisher_information(map_T_robot, robot_T_laser, map_p_reflectors, noise);
  Eigen::FullPivLU<Eigen::Matrix3d> lu(fisher);
  lu.setThreshold(1e-12);
  if (!lu.isInvertible()) return std::nullopt;
  return lu.inverse();
}

}  // namespace refloc
