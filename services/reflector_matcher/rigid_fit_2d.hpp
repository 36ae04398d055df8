#pragma once
// Closed-form least-squares rigid transform between point sets in the plane.
// Written out rather than Eigen::umeyama because it runs per hypothesis on the
// per-scan path, where umeyama's dynamic matrices would allocate.

#include "common/se2.hpp"

#include <Eigen/Core>

namespace refloc {

/// Accumulates correspondences a_p (source) -> b_p (target) and solves for b_T_a.
class RigidFit2d {
 public:
  void clear() { *this = RigidFit2d(); }
  /// Add one correspondence with weight w >= 0.
  void add(const Eigen::Vector2d& a_p, const Eigen::Vector2d& b_p, double w = 1.0);
  int count() const { return count_; }
  /// b_T_a minimising sum w |b_p - b_T_a a_p|^2; false when fewer than 2 points or degenerate.
  bool solve(Pose2& b_T_a) const;

 private:
  int count_ = 0;
  double w_ = 0.0;
  Eigen::Vector2d sum_a_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d sum_b_ = Eigen::Vector2d::Zero();
  Eigen::Matrix2d sum_ab_ = Eigen::Matrix2d::Zero();  ///< sum w a b^T
};

}  // namespace refloc
