#pragma once
// Is a POSE message usable as the matcher's prior? A NaN or absurd prior must never reach
// the tracking gate (which a NaN would pass: every comparison with it is false) nor
// produce an OK match; a rejected POSE is not stored, so the last good one ages out.

#include "common/input_stream_checks.hpp"
#include "reflector_matcher/prior_selector.hpp"

namespace refloc {

struct FusedPoseBounds {
  static constexpr double kMaxAbsCoordinate_m = 1e4;  ///< no site is 10 km across
  static constexpr double kMaxAbsTheta = 6.3;         ///< [rad]; POSE is wrapped to (-pi, pi]
  static constexpr double kMaxVariance = 1e6;         ///< [m^2, rad^2]: fusion's "no information"
};

/// x, y, theta finite and within FusedPoseBounds ("nonfinite", "out_of_bounds"); for a pose
/// with status OK (the only one used as a prior) also a covariance that is symmetric,
/// positive semi-definite, no variance above kMaxVariance ("covariance").
InputFault check_fused_pose(const FusedPose& pose);

}  // namespace refloc
