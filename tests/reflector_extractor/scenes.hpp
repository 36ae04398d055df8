#pragma once
// Scene builders shared by the extractor's tests.

#include "reflector_extractor/synthetic_scan.hpp"

#include <cmath>

namespace refloc::test {

inline Eigen::Vector2d polar(double range, double bearing) {
  return {range * std::cos(bearing), range * std::sin(bearing)};
}

/// A cylinder of radius 0.06 m whose centre is at (range, bearing) in the laser frame.
inline SyntheticCylinder cylinder_at(double range, double bearing, double radius = 0.06) {
  SyntheticCylinder c;
  c.laser_p_center = polar(range, bearing);
  c.radius = radius;
  return c;
}

/// A flat bright strip of this width, centred at (range, bearing), facing the sensor
/// turned by yaw [rad] (0 = seen face on).
inline SyntheticSegment flat_strip(double range, double bearing, double width, double rssi_8bit,
                                   double yaw = 0.0) {
  const Eigen::Vector2d center = polar(range, bearing);
  const Eigen::Vector2d along(-std::sin(bearing + yaw), std::cos(bearing + yaw));
  return SyntheticSegment{center - 0.5 * width * along, center + 0.5 * width * along, rssi_8bit};
}

/// A dull wall 1 m behind the range, so beams that miss a target still echo.
inline SyntheticSegment dull_wall_behind(double range, double bearing) {
  return flat_strip(range + 1.0, bearing, 4.0, 60.0);
}

}  // namespace refloc::test
