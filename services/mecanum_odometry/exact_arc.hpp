#pragma once
// Exact-arc integration: the SE(2) exponential of a constant body twist. A
// robot holding (vx, vy, wz) for dt moves along a circular arc; integrating it
// this way has no first-order error however large the heading change.

#include "common/se2.hpp"
#include "mecanum_odometry/mecanum_kinematics.hpp"

namespace refloc {

/// Body-frame displacement start_T_end after holding a body twist (vx, vy, wz) for dt [s].
Pose2 exp_twist(const BodyTwist& twist, double dt);

/// Inverse of exp_twist for dt = 1: the constant body displacement (twist * dt) that ends at delta.
BodyTwist log_pose(const Pose2& delta);

}  // namespace refloc
