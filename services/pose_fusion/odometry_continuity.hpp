#pragma once
// Turns consecutive ODOMETRY messages into steps for the filter, and notices
// when they are not one continuous odometry frame: a restarted mecanum_odometry
// starts again at the origin with distance 0, and a gap in the messages (the
// service was down, or restarted its integration after an encoder gap) hides
// motion the filter never saw. Applying the pose difference across such a seam
// would teleport the estimate; ignoring the seam would leave the filter
// overconfident about a robot that kept moving. Instead the seam becomes an
// "unobserved motion" step (no displacement across a restart), its covariance
// grown by what the robot could have done meanwhile, so the next laser fix
// re-anchors the estimate.
//
// A step in one frame that moves further than the robot can (kJumpFactor times the
// speed bounds, plus kJumpSlack) is a broken or forged message, not motion: it is
// refused (kImplausible) and the previous message stays the reference. Should
// kResyncAfter messages in a row be refused so (the reference itself was the bad one),
// the next is taken as a new frame (a restart seam), so a stream is never refused forever.

#include "common/odometry_sample.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <optional>

namespace refloc {

struct OdometryContinuityConfig {
  /// Longer between messages: the odometry may have restarted its integration
  /// (mecanum_odometry's max_gap_s) and missed motion [s].
  double max_gap = 1.0;
  double max_speed = 1.5;        ///< bound on the robot's speed during a seam [m/s]
  double max_yaw_rate = 1.5;     ///< bound on its yaw rate during a seam [rad/s]
  double distance_slack = 1e-6;  ///< distance may shrink this much by rounding [m]
};

enum class OdometryStepKind {
  kFirst,        ///< nothing to step from
  kContinuous,   ///< delta is the odometry displacement
  kSeam,         ///< restart (delta identity) or long gap: unobserved_q covers what was missed
  kBackwards,    ///< not after the previous message: nothing to apply, frame restarted
  kImplausible,  ///< moved further than the robot can: refused, nothing to apply
};

struct OdometryStep {
  OdometryStepKind kind = OdometryStepKind::kFirst;
  Pose2 delta;                                             ///< body-frame displacement
  Eigen::Matrix3d unobserved_q = Eigen::Matrix3d::Zero();  ///< kSeam only [m^2, m rad, rad^2]
  double gap = 0.0;                                        ///< time since the previous message [s]
  bool restarted = false;  ///< the odometry frame restarted (distance went back)
};

class OdometryContinuity {
 public:
  explicit OdometryContinuity(const OdometryContinuityConfig& config = {});

  /// The step from the previous sample to this one; this one becomes the previous.
  OdometryStep next(const OdometrySample& sample);

  /// Covariance of motion unobserved for gap [s] under the configured bounds.
  Eigen::Matrix3d unobserved_motion_covariance(double gap) const;

  static constexpr double kJumpFactor = 2.0;
  static constexpr double kJumpSlack_m = 0.05;  ///< [m], and the same number in [rad]
  static constexpr int kResyncAfter = 5;

 private:
  bool implausible(const OdometryStep& step) const;

  OdometryContinuityConfig config_;
  std::optional<OdometrySample> previous_;
  int consecutive_implausible_ = 0;
};

}  // namespace refloc
