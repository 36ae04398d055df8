#pragma once
// Cramér-Rao lower bound of the robot pose from range/bearing measurements of
// known reflectors: no unbiased estimator of (x, y, theta) has a smaller
// covariance. The accuracy tool compares solvers against it.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace refloc {

/// Independent Gaussian noise on each reflector's measured range and bearing.
struct RangeBearingNoise {
  double range_sigma = 0.01;                  ///< [m]
  double bearing_sigma = 0.1 * M_PI / 180.0;  ///< [rad]
};

/// Fisher information of (x, y, theta) of map_T_robot from one range and one bearing to each
/// reflector centre in map_p_reflectors (those in view) [1/m^2, 1/(m rad), 1/rad^2].
Eigen::Matrix3d pose_fisher_information(const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                        const std::vector<Eigen::Vector2d>& map_p_reflectors,
                                        const RangeBearingNoise& noise);

/// CRLB covariance of (x, y, theta) [m^2, m rad, rad^2]; empty when the geometry does not
/// determine the pose (fewer than 2 reflectors, or all on a line through the sensor).
std::optional<Eigen::Matrix3d> pose_crlb(const Pose2& map_T_robot, const Pose2& robot_T_laser,
                                         const std::vector<Eigen::Vector2d>& map_p_reflectors,
                                         const RangeBearingNoise& noise);

}  // namespace refloc
