#include "pose_fusion/odometry_continuity.hpp"

namespace refloc {

OdometryContinuity::OdometryContinuity(const OdometryContinuityConfig& config) : config_(config) {}

Eigen::Matrix3d OdometryContinuity::unobserved_motion_covariance(double gap) const {
  const double sxy = config_.max_speed * gap;
  const double st = config_.max_yaw_rate * gap;
  return Eigen::Vector3d(sxy * sxy, sxy * sxy, st * st).asDiagonal();
}

OdometryStep OdometryContinuity::next(const OdometrySample& sample) {
  OdometryStep step;
  if (!previous_) {
    previous_ = sample;
    return step;
  }
  const OdometrySample previous = *previous_;
  previous_ = sample;
  step.gap = 1e-6 * static_cast<double>(sample.utime - previous.utime);
  step.restarted = sample.distance < previous.distance - config_.distance_slack;
  if (sample.utime <= previous.utime) {
    step.kind = OdometryStepKind::kBackwards;
    step.restarted = true;
    return step;
  }
  // Across a restart the two poses are in different frames: their difference
  // means nothing. Across a long gap in one frame it is whatever the odometry
  // managed to integrate (everything, or nothing when it restarted integration).
  if (!step.restarted) step.delta = previous.odom_T_robot.inverse() * sample.odom_T_robot;
  if (step.restarted || step.gap > config_.max_gap) {
    step.kind = OdometryStepKind::kSeam;
    step.unobserved_q = unobserved_motion_covariance(step.gap);
    return step;
  }
  step.kind = OdometryStepKind::kContinuous;
  return step;
}

}  // namespace refloc
