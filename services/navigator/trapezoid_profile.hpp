#pragma once
// Trapezoidal velocity profiles as feedback: the speed wanted at a remaining
// distance is capped by max_speed and by the speed from which the robot can
// still brake to creep_speed at creep_distance; the commanded velocity moves
// toward it by at most max_accel per control period. Accelerate, cruise,
// decelerate: a trapezoid, recomputed from the measured pose every period.
// Inside creep_distance the speed is proportional to the distance (capped at
// creep_speed), so the final approach converges instead of overshooting.

#include <Eigen/Core>

namespace refloc {

struct ProfileLimits {
  double max_speed = 1.0;        ///< [m/s] or [rad/s]
  double max_accel = 0.5;        ///< [m/s^2] or [rad/s^2]
  double brake_fraction = 0.8;   ///< braking plans with this share of max_accel (margin for lag)
  double creep_distance = 0.03;  ///< final approach starts here [m] or [rad]
  double creep_speed = 0.03;     ///< [m/s] or [rad/s]
  double gain = 2.0;             ///< final approach speed per remaining distance [1/s]
};

/// Speed (>= 0) wanted with remaining distance (>= 0) to the target.
double approach_speed(double remaining, const ProfileLimits& limits);

/// current moved toward target by at most max_step (per component).
double rate_limit(double current, double target, double max_step);

/// current moved toward target by a vector step of norm at most max_step.
Eigen::Vector2d rate_limit(const Eigen::Vector2d& current, const Eigen::Vector2d& target, double max_step);

}  // namespace refloc
