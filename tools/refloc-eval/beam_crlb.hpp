#pragma once
// Cramér-Rao bound of the robot pose from the raw LMS100 measurements: every
// beam that lies fully on a reflector measures a range to a circle of known
// centre and radius with Gaussian noise sigma. No estimator that uses those
// ranges can beat this covariance; the accuracy study reports RMSE / bound.

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace refloc {

struct ReflectorBeam {
  double beam_angle = 0.0;  ///< in the laser frame [rad]
  int reflector_index = 0;  ///< into ReflectorMap::reflectors
};

/// Covariance bound of (x, y, theta) of map_T_robot [m^2, m rad, rad^2]; empty with fewer than
/// 3 informative beams or a singular geometry.
std::optional<Eigen::Matrix3d> beam_range_crlb(const ReflectorMap& map, const Pose2& map_T_robot,
                                               const Pose2& robot_T_laser, const std::vector<ReflectorBeam>& beams,
                                               double range_sigma);

}  // namespace refloc
