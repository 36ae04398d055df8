#include "mecanum_odometry/mecanum_odometry.hpp"

#include "common/covariance_propagation.hpp"
#include "mecanum_odometry/encoder_ticks.hpp"

#include <cmath>

namespace refloc {

MecanumOdometry::MecanumOdometry(const RobotConfig& robot, const OdometryConfig& config)
    : kinematics_(robot),
      noise_(robot.odometry_noise),
      config_(config),
      rad_per_tick_(2.0 * M_PI / robot.encoder_ticks_per_rev) {}

EncoderSampleResult MecanumOdometry::add_sample(int64_t utime, const std::array<int32_t, 4>& ticks) {
  if (!has_previous_) {
    has_previous_ = true;
    previous_utime_ = utime;
    previous_ticks_ = ticks;
    estimate_.utime = utime;
    return EncoderSampleResult::kFirstSample;
  }
  if (utime <= previous_utime_) return EncoderSampleResult::kOutOfOrder;
  const double dt = 1e-6 * static_cast<double>(utime - previous_utime_);
  WheelArray angle{};
  double max_speed = 0.0;
  for (size_t i = 0; i < 4; ++i) {
    angle[i] = rad_per_tick_ * tick_delta(ticks[i], previous_ticks_[i]);
    max_speed = std::max(max_speed, std::abs(angle[i]) / dt);
  }
  previous_utime_ = utime;
  previous_ticks_ = ticks;
  estimate_.utime = utime;
  if (!(dt <= config_.max_gap)) {
    estimate_.twist = {};
    return EncoderSampleResult::kGapRestart;
  }
  if (!(max_speed <= config_.max_plausible_wheel_speed)) {
    estimate_.twist = {};
    return EncoderSampleResult::kImplausible;
  }
  // Wheel angles over the interval give the body displacement of a constant
  // twist held for dt; se2_exp turns it into the exact arc.
  const BodyTwist displacement = kinematics_.forward(angle);
  const Pose2 delta = se2_exp(displacement);
  estimate_.covariance = compose_covariance(estimate_.odom_T_robot, estimate_.covariance, delta,
                                            increment_covariance(delta, noise_));
  estimate_.odom_T_robot = estimate_.odom_T_robot * delta;
  estimate_.twist = {displacement.vx / dt, displacement.vy / dt, displacement.wz / dt};
  estimate_.distance += std::hypot(displacement.vx, displacement.vy);
  estimate_.slip_indicator = std::abs(kinematics_.redundancy_residual(angle)) / dt;
  estimate_.last_increment = delta;
  return EncoderSampleResult::kIntegrated;
}

void MecanumOdometry::restart_from(int64_t utime, const std::array<int32_t, 4>& ticks) {
  has_previous_ = true;
  previous_utime_ = utime;
  previous_ticks_ = ticks;
  estimate_.utime = utime;
  estimate_.twist = {};
  estimate_.slip_indicator = 0.0;
  estimate_.last_increment = {};
}

}  // namespace refloc
