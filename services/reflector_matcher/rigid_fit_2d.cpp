#include "reflector_matcher/rigid_fit_2d.hpp"

#include <cmath>

namespace refloc {

void RigidFit2d::add(const Eigen::Vector2d& a_p, const Eigen::Vector2d& b_p, double w) {
  ++count_;
  w_ += w;
  sum_a_ += w * a_p;
  sum_b_ += w * b_p;
  sum_ab_ += w * a_p * b_p.transpose();
}

bool RigidFit2d::solve(Pose2& b_T_a) const {
  if (count_ < 2 || w_ <= 0.0) return false;
  const Eigen::Vector2d ca = sum_a_ / w_, cb = sum_b_ / w_;
  // Centred cross-covariance H = sum w (a - ca)(b - cb)^T.
  const Eigen::Matrix2d h = sum_ab_ - w_ * ca * cb.transpose();
  const double dot = h(0, 0) + h(1, 1);    // sum of a'.b'
  const double cross = h(0, 1) - h(1, 0);  // sum of a' x b'
  if (std::abs(dot) + std::abs(cross) < 1e-12) return false;
  const double theta = std::atan2(cross, dot);
  const double c = std::cos(theta), s = std::sin(theta);
  b_T_a.theta = theta;
  b_T_a.x = cb.x() - (c * ca.x() - s * ca.y());
  b_T_a.y = cb.y() - (s * ca.x() + c * ca.y());
  return true;
}

}  // namespace refloc
