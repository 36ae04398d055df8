#pragma once
// Small 2-D helpers the world renderer and the survey's visibility both need.

#include <Eigen/Core>

#include <algorithm>

namespace refloc {

/// z of the cross product of two plane vectors (a.x b.y - a.y b.x).
inline double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// Distance from p to the segment a-b (a != b) [m].
inline double point_segment_distance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                                     const Eigen::Vector2d& b) {
  const Eigen::Vector2d e = b - a;
  const double t = std::clamp((p - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
  return (a + t * e - p).norm();
}

}  // namespace refloc
