#pragma once
// The paper's §3.6 pose computation, kept as the baseline:
//   eq. 4   circle equations (X_i - X0')^2 + (Y_i - Y0')^2 = R_i^2, subtracted pairwise (all
//           C(n,2) pairs) into a linear least-squares problem for the laser position (X0', Y0');
//   eq. 6-7 alpha_i = atan2(Y_i - Y0', X_i - X0') - theta_i, averaged arithmetically;
//   eq. 8   X0 = X0' + OO' cos(alpha_o - beta), Y0 = Y0' + OO' sin(alpha_o - beta), the
//           offset from the laser to the robot centre.

#include "pose_solver/point_observation.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// Eq. 4: least-squares laser position from ranges to known centres; false with < 3
/// observations or (nearly) collinear reflectors (smallest/largest eigenvalue < min_conditioning).
bool trilaterate_position(const std::vector<PointObservation>& observations, const std::vector<char>* use,
                          double min_conditioning, Eigen::Vector2d& map_p_laser);

/// Eq. 6-7: the paper's arithmetic mean of the wrapped alpha_i [rad] (wrong near +-pi, kept as published).
double paper_mean_heading(const std::vector<PointObservation>& observations,
                          const Eigen::Vector2d& map_p_laser);

/// Eq. 6 with a circular mean instead of eq. 7 [rad].
double circular_mean_heading(const std::vector<PointObservation>& observations, const std::vector<char>* use,
                             const Eigen::Vector2d& map_p_laser);

/// Eq. 8: robot centre from the laser position and the robot heading alpha_o [rad], with
/// OO' = |robot_p_laser| [m] and beta = -atan2(-y, -x) of robot_p_laser [rad].
Eigen::Vector2d paper_robot_position(const Eigen::Vector2d& map_p_laser, double robot_heading,
                                     const Pose2& robot_T_laser);

}  // namespace refloc
