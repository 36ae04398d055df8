#pragma once
// Which LASER_POSE messages the filter may use, and how: the solver's OK may
// (re-)initialise, its DEGRADED (few reflectors) only corrects; LOST, AMBIGUOUS and
// INITIALIZING carry no pose, and a non-finite pose or a covariance that is not
// positive on its diagonal is unusable whatever the status says.

#include "common/se2.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>

namespace refloc {

/// The solver's status of a LASER_POSE, as far as fusion distinguishes it (pose2d_t::STATUS_*).
enum class FixStatus { kOk, kDegraded, kNoPose };

/// One LASER_POSE message (pose2d_t) as a plain struct.
struct LaserFixInput {
  int64_t utime = 0;  ///< time of the scan the pose refers to [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2, m rad, rad^2]
  FixStatus status = FixStatus::kNoPose;
  int32_t reflectors_used = 0;
};

/// The fix the filter can use, or nothing (status without a pose, non-finite values,
/// covariance not positive on the diagonal).
std::optional<PoseFix> usable_fix(const LaserFixInput& input);

}  // namespace refloc
