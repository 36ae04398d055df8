#pragma once
// Is the covariance a live stack publishes honest? The NEES (fix_consistency.hpp) of each
// published pose against GROUND_TRUTH interpolated at the pose's own stamp, the way
// compare() in trajectory.hpp matches them for the RMSE.

#include "fix_consistency.hpp"
#include "trajectory.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

/// A published pose with the covariance it came with.
struct StampedFix {
  int64_t utime = 0;  ///< [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of (x [m], y [m], theta [rad])
};

/// NEES of each fix at or after from_utime [us] whose time the truth covers (Trajectory::at);
/// the others are not counted.
ConsistencySummary consistency_against_truth(const std::vector<StampedFix>& fixes, const Trajectory& truth,
                                             int64_t from_utime = 0);

}  // namespace refloc
