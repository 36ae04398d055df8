#include "pose_fusion/laser_fix_input.hpp"

#include <cmath>

namespace refloc {

std::optional<PoseFix> usable_fix(const LaserFixInput& input) {
  PoseFix fix;
  if (input.status == FixStatus::kOk) {
    fix.quality = FixQuality::kGood;
  } else if (input.status == FixStatus::kDegraded) {
    fix.quality = FixQuality::kUsable;
  } else {
    return std::nullopt;
  }
  fix.utime = input.utime;
  fix.map_T_robot = input.map_T_robot;
  fix.covariance = input.covariance;
  const Pose2& p = input.map_T_robot;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.theta) || !fix.covariance.allFinite() ||
      fix.covariance.diagonal().minCoeff() <= 0.0) {
    return std::nullopt;
  }
  return fix;
}

}  // namespace refloc
