#include "common/mecanum_kinematics.hpp"

namespace refloc {

MecanumKinematics::MecanumKinematics(double wheel_radius, double lx, double ly)
    : r_(wheel_radius), k_(lx + ly) {}

WheelArray MecanumKinematics::inverse(const BodyTwist& t) const {
  const double rot = k_ * t.wz;
  return {(t.vx - t.vy - rot) / r_, (t.vx + t.vy + rot) / r_, (t.vx - t.vy + rot) / r_,
          (t.vx + t.vy - rot) / r_};
}

BodyTwist MecanumKinematics::forward(const WheelArray& w) const {
  // Pseudo-inverse of the 4x3 inverse-kinematics matrix (its columns are orthogonal).
  const double q = r_ / 4.0;
  return {q * (w[0] + w[1] + w[2] + w[3]), q * (-w[0] + w[1] - w[2] + w[3]),
          q / k_ * (-w[0] + w[1] + w[2] - w[3])};
}

double MecanumKinematics::redundancy_residual(const WheelArray& w) const {
  return r_ / 4.0 * (w[0] + w[1] - w[2] - w[3]);
}

}  // namespace refloc
