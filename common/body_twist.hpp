#pragma once
// The one planar twist type of refloc (the tangent space of SE(2), see se2.hpp).

namespace refloc {

/// A body velocity in the robot's own frame [m/s, m/s, rad/s] or, integrated over
/// an interval, a body displacement [m, m, rad]. +vx forward, +vy left, +wz
/// counter-clockwise.
struct BodyTwist {
  double vx = 0.0;
  double vy = 0.0;
  double wz = 0.0;
};

}  // namespace refloc
