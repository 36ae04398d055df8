#pragma once
// SE(2) geometry. Frame naming follows Sophus: a_T_b takes points in frame b
// into frame a, a_p_x is point x expressed in frame a. BodyTwist is the tangent
// space; se2_exp / se2_log map between the two.

#include "common/angles.hpp"
#include "common/body_twist.hpp"

#include <Eigen/Core>

namespace refloc {

/// A rigid transform in the plane: rotation by theta [rad], then translation (x, y) [m].
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;

  Eigen::Vector2d translation() const { return {x, y}; }
  Eigen::Matrix2d rotation() const;
  Eigen::Matrix3d matrix() const;  ///< homogeneous 3x3

  /// a_T_c = a_T_b * b_T_c
  Pose2 operator*(const Pose2& b_T_c) const;
  /// a_p = a_T_b * b_p
  Eigen::Vector2d operator*(const Eigen::Vector2d& b_p) const;
  Pose2 inverse() const;
};

/// Same pose up to tol_m in translation and tol_rad in wrapped heading.
bool approx_equal(const Pose2& a, const Pose2& b, double tol_m, double tol_rad);

/// The SE(2) exponential: start_T_end of a frame holding a constant body twist for
/// dt [s], an exact circular arc. Heading wrapped to (-pi, pi] like every Pose2.
Pose2 se2_exp(const BodyTwist& twist, double dt = 1.0);

/// The SE(2) logarithm, inverse of se2_exp for dt = 1: the constant body displacement
/// [m, m, rad] whose arc ends at start_T_end. wz = wrap_angle(start_T_end.theta), so
/// se2_exp(se2_log(x)) == x for every x and se2_log(se2_exp(t)) == t for |t.wz| < pi.
BodyTwist se2_log(const Pose2& start_T_end);

}  // namespace refloc
