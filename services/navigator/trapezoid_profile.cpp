#include "navigator/trapezoid_profile.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

double approach_speed(double remaining, const ProfileLimits& limits) {
  if (remaining <= limits.creep_distance) {
    return std::min(limits.creep_speed, limits.gain * remaining);
  }
  const double brake = limits.brake_fraction * limits.max_accel;
  const double braking_speed =
      std::sqrt(limits.creep_speed * limits.creep_speed + 2.0 * brake * (remaining - limits.creep_distance));
  return std::min(limits.max_speed, braking_speed);
}

double rate_limit(double current, double target, double max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

Eigen::Vector2d rate_limit(const Eigen::Vector2d& current, const Eigen::Vector2d& target, double max_step) {
  const Eigen::Vector2d change = target - current;
  const double norm = change.norm();
  if (norm <= max_step) return target;
  return current + change * (max_step / norm);
}

}  // namespace refloc
