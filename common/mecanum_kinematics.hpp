#pragma once
// Kinematics of a four-Mecanum-wheel base with standard X-arrangement rollers
// (45 deg rollers; the base can translate in any direction and rotate).
//
// Wheel order: front-left, front-right, rear-right, rear-left. Body frame:
// +vx forward, +vy left, +wz counter-clockwise. A positive wheel speed drives
// that wheel's contact point forward. With k = lx + ly:
//   w_fl = (vx - vy - k wz) / r        w_fr = (vx + vy + k wz) / r
//   w_rr = (vx - vy + k wz) / r        w_rl = (vx + vy - k wz) / r
// Four equations for three unknowns: the forward kinematics is the least-squares
// solution, and the left-over direction (w_fl + w_fr - w_rr - w_rl), zero for
// any rigid body motion, measures how much the wheels disagree (slip).

#include "common/body_twist.hpp"
#include "common/robot_config.hpp"

#include <array>

namespace refloc {

/// Four wheel values in the order front-left, front-right, rear-right, rear-left.
using WheelArray = std::array<double, 4>;

class MecanumKinematics {
 public:
  /// wheel_radius [m], lx half wheelbase [m], ly half track [m].
  MecanumKinematics(double wheel_radius, double lx, double ly);
  explicit MecanumKinematics(const RobotConfig& robot)
      : MecanumKinematics(robot.wheel_radius, robot.half_wheelbase_lx, robot.half_track_ly) {}

  /// Wheel speeds [rad/s] that realise a body twist (also: angles [rad] for a displacement).
  WheelArray inverse(const BodyTwist& twist) const;
  /// Least-squares body twist [m/s, m/s, rad/s] from wheel speeds [rad/s].
  BodyTwist forward(const WheelArray& wheel) const;
  /// Residual of the fourth (redundant) equation, r/4 * (w_fl + w_fr - w_rr - w_rl) [m/s
  /// for speeds, m for angles]; 0 when the wheels agree on one rigid motion.
  double redundancy_residual(const WheelArray& wheel) const;

  double wheel_radius() const { return r_; }

 private:
  double r_;
  double k_;  ///< lx + ly [m]
};

}  // namespace refloc
