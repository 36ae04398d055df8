#include "pose_fusion/fusion_input_checks.hpp"

#include "common/input_sanity.hpp"

namespace refloc {

const char* to_string(InputProblem problem) {
  switch (problem) {
    case InputProblem::kNone:
      return "none";
    case InputProblem::kNonFinite:
      return "nonfinite";
    case InputProblem::kOutOfBounds:
      return "out_of_bounds";
    case InputProblem::kCovariance:
      return "covariance";
  }
  return "unknown";
}

namespace {

bool pose_within_bounds(const Pose2& p) {
  return finite_abs_at_most(p.x, kMaxAbsPosition_m) && finite_abs_at_most(p.y, kMaxAbsPosition_m) &&
         finite_abs_at_most(p.theta, kMaxAbsHeading_rad);
}

}  // namespace

InputProblem check_odometry_values(const OdometrySample& s) {
  const Pose2& p = s.odom_T_robot;
  if (!all_finite({p.x, p.y, p.theta, s.twist.vx, s.twist.vy, s.twist.wz, s.distance}))
    return InputProblem::kNonFinite;
  if (!pose_within_bounds(p) || !finite_within(s.distance, 0.0, kMaxDistance_m) ||
      !finite_abs_at_most(s.twist.vx, kMaxAbsSpeed_m_s) ||
      !finite_abs_at_most(s.twist.vy, kMaxAbsSpeed_m_s) ||
      !finite_abs_at_most(s.twist.wz, kMaxAbsYawRate_rad_s)) {
    return InputProblem::kOutOfBounds;
  }
  return InputProblem::kNone;
}

InputProblem check_fix_values(const LaserFixInput& in) {
  const Pose2& p = in.map_T_robot;
  if (!all_finite({p.x, p.y, p.theta}) || !in.covariance.allFinite()) return InputProblem::kNonFinite;
  if (!pose_within_bounds(p)) return InputProblem::kOutOfBounds;
  // A zero variance would make the filter certain: the diagonal must be positive.
  if (!is_usable_covariance(in.covariance, kMaxFixVariance) || !(in.covariance.diagonal().minCoeff() > 0.0))
    return InputProblem::kCovariance;
  return InputProblem::kNone;
}

}  // namespace refloc
