#include "pose_fusion/odometry_continuity.hpp"

#include <cmath>

namespace refloc {

OdometryContinuity::OdometryContinuity(const OdometryContinuityConfig& config) : config_(config) {}

Eigen::Matrix3d OdometryContinuity::unobserved_motion_covariance(double gap) const {
  const double sxy = config_.max_speed * gap;
  const double st = config_.max_yaw_rate * gap;
  return Eigen::Vector3d(sxy * sxy, sxy * sxy, st * st).asDiagonal();
}

bool OdometryContinuity::implausible(const OdometryStep& step) const {
  const double reach_m = kJumpFactor * config_.max_speed * step.gap + kJumpSlack_m;
  const double reach_rad = kJumpFactor * config_.max_yaw_rate * step.gap + kJumpSlack_m;
  return !(std::hypot(step.delta.x, step.delta.y) <= reach_m && std::abs(step.delta.theta) <= reach_rad);
}

OdometryStep OdometryContinuity::next(const OdometrySample& sample) {
  OdometryStep step;
  if (!previous_) {
    previous_ = sample;
    return step;
  }
  const OdometrySample previous = *previous_;
  step.gap = 1e-6 * static_cast<double>(sample.utime - previous.utime);
  step.restarted = sample.distance < previous.distance - config_.distance_slack;
  if (sample.utime <= previous.utime) {
    previous_ = sample;
    consecutive_implausible_ = 0;
    step.kind = OdometryStepKind::kBackwards;
    step.restarted = true;
    return step;
  }
  // Across a restart the two poses are in different frames: their difference
  // means nothing. Across a long gap in one frame it is whatever the odometry
  // managed to integrate (everything, or nothing when it restarted integration).
  if (!step.restarted) step.delta = previous.odom_T_robot.inverse() * sample.odom_T_robot;
  if (!step.restarted && implausible(step)) {
    if (++consecutive_implausible_ <= kResyncAfter) {
      step.kind = OdometryStepKind::kImplausible;
      return step;
    }
    step.restarted = true;  // the reference was the bad one: a new frame from here
    step.delta = Pose2{};
  }
  previous_ = sample;
  consecutive_implausible_ = 0;
  if (step.restarted || step.gap > config_.max_gap) {
    step.kind = OdometryStepKind::kSeam;
    step.unobserved_q = unobserved_motion_covariance(step.gap);
    return step;
  }
  step.kind = OdometryStepKind::kContinuous;
  return step;
}

}  // namespace refloc
