#pragma once
// What the solver says about one scan.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// Same meaning as pose2d_t::STATUS_OK / STATUS_DEGRADED / STATUS_LOST.
enum class SolveStatus { kOk, kDegraded, kLost };

/// What the scan did with the range offset b (range_bias_refinement.hpp).
enum class RangeBiasUse {
  kEstimated,      ///< b estimated jointly with the pose; covariance is the marginal
  kFewReflectors,  ///< fewer than range_bias.min_reflectors used: b held, its sigma in the covariance
  kWeakGeometry,   ///< the scan alone gives b a sigma above range_bias.max_scan_sigma: held, inflated
  kNotEstimating,  ///< range_bias.estimate is false: held at the prior, inflated by its sigma
  kNoSolution,     ///< no pose (or paper mode, which does not model b)
};

struct PoseSolution {
  SolveStatus status = SolveStatus::kLost;
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();  ///< of (x, y, theta) [m^2, m rad, rad^2]
  int reflectors_used = 0;
  double rms_residual = 0.0;  ///< RMS of range residuals over the reflectors used [m]
  int iterations = 0;
  std::vector<char> used;  ///< per match: 1 when it took part in the final solution
  RangeBiasUse range_bias_use = RangeBiasUse::kNoSolution;
  double range_bias = 0.0;        ///< [m] offset taken off every range (measured - true)
  double range_bias_sigma = 0.0;  ///< [m] its sigma after this scan (the prior's when held)
  /// [m] what this scan's data alone say about b (range_bias_scan_sigma); infinite: nothing
  double range_bias_scan_sigma = 0.0;
};

}  // namespace refloc
