#include "reflector_matcher/fused_pose_check.hpp"

#include "common/input_sanity.hpp"

#include <fmt/format.h>

namespace refloc {

InputFault check_fused_pose(const FusedPose& pose) {
  const Pose2& p = pose.map_T_robot;
  if (!all_finite({p.x, p.y, p.theta}))
    return {"nonfinite", fmt::format("pose ({}, {}, {})", p.x, p.y, p.theta)};
  if (!finite_abs_at_most(p.x, FusedPoseBounds::kMaxAbsCoordinate_m) ||
      !finite_abs_at_most(p.y, FusedPoseBounds::kMaxAbsCoordinate_m) ||
      !finite_abs_at_most(p.theta, FusedPoseBounds::kMaxAbsTheta))
    return {"out_of_bounds", fmt::format("pose ({} m, {} m, {} rad)", p.x, p.y, p.theta)};
  if (pose.ok && !is_usable_covariance(pose.covariance, FusedPoseBounds::kMaxVariance))
    return {"covariance", fmt::format("covariance diagonal ({}, {}, {})", pose.covariance(0, 0),
                                      pose.covariance(1, 1), pose.covariance(2, 2))};
  return {};
}

}  // namespace refloc
