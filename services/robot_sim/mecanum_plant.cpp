#include "robot_sim/mecanum_plant.hpp"

#include "common/se2.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

MecanumPlant::MecanumPlant(const RobotConfig& robot, const PlantConfig& config, const Pose2& map_T_robot,
                           int64_t start_utime)
    : robot_(robot),
      config_(config),
      kinematics_(robot),
      map_T_robot_(map_T_robot),
      utime_(start_utime),
      rng_(config.slip.seed) {}

void MecanumPlant::command(const BodyTwist& twist, int64_t utime) {
  command_ = twist;
  command_utime_ = utime;
  has_command_ = true;
}

bool MecanumPlant::command_stale() const {
  return !has_command_ || static_cast<double>(utime_ - command_utime_) > config_.command_timeout * 1e6;
}

void MecanumPlant::advance_to(int64_t utime) {
  const auto step_us = static_cast<int64_t>(std::llround(config_.step * 1e6));
  while (utime_ + step_us <= utime) {
    utime_ += step_us;
    step(config_.step);
  }
  if (utime > utime_) {  // the remainder, so the plant time matches exactly
    step(1e-6 * static_cast<double>(utime - utime_));
    utime_ = utime;
  }
}

void MecanumPlant::step(double dt) {
  WheelArray target = command_stale() ? WheelArray{} : kinematics_.inverse(command_);
  double largest = 0.0;
  for (double w : target) largest = std::max(largest, std::abs(w));
  if (largest > robot_.max_wheel_speed) {
    for (double& w : target) w *= robot_.max_wheel_speed / largest;
  }
  double largest_change = 0.0;
  for (size_t i = 0; i < 4; ++i) {
    largest_change = std::max(largest_change, std::abs(target[i] - wheel_speed_[i]));
  }
  const double max_change = robot_.max_wheel_accel * dt;
  const double ramp = largest_change > max_change ? max_change / largest_change : 1.0;
  WheelArray ground{};
  for (size_t i = 0; i < 4; ++i) {
    const double previous = wheel_speed_[i];
    wheel_speed_[i] += ramp * (target[i] - previous);
    const double mean_speed = 0.5 * (previous + wheel_speed_[i]);
    wheel_angle_[i] += mean_speed * (1.0 + config_.slip.spin_excess[i]) * dt;
    ground[i] = mean_speed * (1.0 + config_.slip.scale_error[i]);
  }
  // The body follows the least-squares motion of the four contact points.
  body_twist_ = kinematics_.forward(ground);
  if (config_.slip.lateral_noise_per_speed > 0.0) {
    const double speed = std::hypot(body_twist_.vx, body_twist_.vy);
    body_twist_.vy += config_.slip.lateral_noise_per_speed * speed * unit_normal_(rng_);
  }
  map_T_robot_ = map_T_robot_ * se2_exp(body_twist_, dt);
}

}  // namespace refloc
