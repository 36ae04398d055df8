#include "mecanum_odometry/exact_arc.hpp"

#include <cmath>

namespace refloc {
namespace {

// sin(a)/a and (1 - cos(a))/a with Taylor series near 0, where the ratios lose precision.
void arc_coefficients(double a, double& sin_over_a, double& one_minus_cos_over_a) {
  if (std::abs(a) < 1e-6) {
    sin_over_a = 1.0 - a * a / 6.0;
    one_minus_cos_over_a = a / 2.0 - a * a * a / 24.0;
  } else {
    sin_over_a = std::sin(a) / a;
    one_minus_cos_over_a = (1.0 - std::cos(a)) / a;
  }
}

}  // namespace

Pose2 exp_twist(const BodyTwist& twist, double dt) {
  const double dx = twist.vx * dt, dy = twist.vy * dt, a = twist.wz * dt;
  double s, c;
  arc_coefficients(a, s, c);
  return {s * dx - c * dy, c * dx + s * dy, wrap_angle(a)};
}

BodyTwist log_pose(const Pose2& delta) {
  const double a = delta.theta;
  double s, c;
  arc_coefficients(a, s, c);
  // Invert [s -c; c s] (determinant s^2 + c^2 > 0 for |a| < 2 pi).
  const double det = s * s + c * c;
  return {(s * delta.x + c * delta.y) / det, (-c * delta.x + s * delta.y) / det, a};
}

}  // namespace refloc
