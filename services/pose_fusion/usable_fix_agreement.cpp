#include "pose_fusion/usable_fix_agreement.hpp"

#include "common/covariance_propagation.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace refloc {

void UsableFixAgreement::add_odometry(const Pose2& delta, const Eigen::Matrix3d& q) {
  for (Pending& p : pending_) {
    p.covariance = compose_covariance(p.map_T_robot, p.covariance, delta, q);
    p.map_T_robot = p.map_T_robot * delta;
  }
}

bool UsableFixAgreement::offer(int64_t fix_utime, const Pose2& map_T_robot_now,
                               const Eigen::Matrix3d& covariance_now) {
  if (!enabled()) return false;
  pending_.erase(std::remove_if(pending_.begin(), pending_.end(),
                                [&](const Pending& p) { return p.utime < fix_utime - window_us_; }),
                 pending_.end());
  int agreeing = 1;
  int64_t oldest = fix_utime;
  for (const Pending& p : pending_) {
    Eigen::Vector3d d(map_T_robot_now.x - p.map_T_robot.x, map_T_robot_now.y - p.map_T_robot.y,
                      std::remainder(map_T_robot_now.theta - p.map_T_robot.theta, 2.0 * M_PI));
    const Eigen::Matrix3d s = covariance_now + p.covariance;
    const double m2 = d.dot(s.fullPivLu().solve(d));
    if (m2 <= gate_chi2_) {  // NaN disagrees
      ++agreeing;
      oldest = std::min(oldest, p.utime);
    }
  }
  if (agreeing >= needed_) {
    last_agreeing_ = agreeing;
    last_span_s_ = static_cast<double>(fix_utime - oldest) * 1e-6;
    return true;
  }
  if (pending_.size() >= kMaxPending) pending_.erase(pending_.begin());
  pending_.push_back({fix_utime, map_T_robot_now, covariance_now});
  return false;
}

}  // namespace refloc
