#pragma once
// What the solver says about one scan.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// Same meaning as pose2d_t::STATUS_OK / STATUS_DEGRADED / STATUS_LOST.
enum class SolveStatus { kOk, kDegraded, kLost };

struct PoseSolution {
  SolveStatus status = SolveStatus::kLost;
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< of (x, y, theta) [m^2, m rad, rad^2]
  int reflectors_used = 0;
  double rms_residual = 0.0;  ///< RMS of range residuals over the reflectors used [m]
  int iterations = 0;
  std::vector<char> used;  ///< per match: 1 when it took part in the final solution
};

}  // namespace refloc
