#include "pose_solver/laser_fix.hpp"

#include "common/input_sanity.hpp"

namespace refloc {
namespace {

LaserFixStatus from_solution(SolveStatus s) {
  switch (s) {
    case SolveStatus::kOk:
      return LaserFixStatus::kOk;
    case SolveStatus::kDegraded:
      return LaserFixStatus::kDegraded;
    case SolveStatus::kLost:
      break;
  }
  return LaserFixStatus::kLost;
}

}  // namespace

LaserFix make_laser_fix(int64_t utime, MatchVerdict verdict, const PoseSolution& solution, int matches) {
  LaserFix fix;
  fix.utime = utime;
  if (verdict != MatchVerdict::kOk) {
    fix.status = verdict == MatchVerdict::kAmbiguous ? LaserFixStatus::kAmbiguous : LaserFixStatus::kLost;
    return fix;
  }
  fix.status = from_solution(solution.status);
  fix.has_pose = solution.status != SolveStatus::kLost;
  if (!fix.has_pose) return fix;
  // What a solver made of finite input can still overflow or be singular: checked here,
  // the last step before LASER_POSE, so nothing non-finite or an OK from it is published.
  const Pose2& p = solution.map_T_robot;
  if (!all_finite({p.x, p.y, p.theta, solution.rms_residual}) ||
      !is_usable_covariance(solution.covariance, kMaxFixVariance)) {
    fix.status = LaserFixStatus::kLost;
    fix.has_pose = false;
    fix.unusable_solution = true;
    return fix;
  }
  fix.map_T_robot = solution.map_T_robot;
  fix.covariance = solution.covariance;
  fix.reflectors_used = solution.reflectors_used;
  fix.residual = solution.rms_residual;
  fix.range_bias_use = solution.range_bias_use;
  fix.range_bias = solution.range_bias;
  fix.range_bias_sigma = solution.range_bias_sigma;
  if (solution.reflectors_used < matches) fix.outlier_matches = matches - solution.reflectors_used;
  return fix;
}

}  // namespace refloc
