#include "common/se2.hpp"

#include <cmath>

namespace refloc {

namespace {

// sin(a)/a and (1 - cos(a))/a, the entries of the SE(2) exponential's V(a), with
// their Taylor series near 0 where the ratios lose precision.
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

Eigen::Matrix2d Pose2::rotation() const {
  const double c = std::cos(theta), s = std::sin(theta);
  Eigen::Matrix2d r;
  r << c, -s, s, c;
  return r;
}

Eigen::Matrix3d Pose2::matrix() const {
  Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
  m.topLeftCorner<2, 2>() = rotation();
  m(0, 2) = x;
  m(1, 2) = y;
  return m;
}

Pose2 Pose2::operator*(const Pose2& b_T_c) const {
  const Eigen::Vector2d t = (*this) * b_T_c.translation();
  return {t.x(), t.y(), wrap_angle(theta + b_T_c.theta)};
}

Eigen::Vector2d Pose2::operator*(const Eigen::Vector2d& b_p) const {
  const double c = std::cos(theta), s = std::sin(theta);
  return {x + c * b_p.x() - s * b_p.y(), y + s * b_p.x() + c * b_p.y()};
}

Pose2 Pose2::inverse() const {
  const double c = std::cos(theta), s = std::sin(theta);
  return {-(c * x + s * y), -(-s * x + c * y), wrap_angle(-theta)};
}

bool approx_equal(const Pose2& a, const Pose2& b, double tol_m, double tol_rad) {
  return std::hypot(a.x - b.x, a.y - b.y) <= tol_m && std::abs(angle_diff(a.theta, b.theta)) <= tol_rad;
}

Pose2 se2_exp(const BodyTwist& twist, double dt) {
  const double dx = twist.vx * dt, dy = twist.vy * dt, a = twist.wz * dt;
  double s, c;
  arc_coefficients(a, s, c);
  return {s * dx - c * dy, c * dx + s * dy, wrap_angle(a)};
}

BodyTwist se2_log(const Pose2& start_T_end) {
  const double a = wrap_angle(start_T_end.theta);
  double s, c;
  arc_coefficients(a, s, c);
  // Invert V(a) = [s -c; c s] (determinant s^2 + c^2 > 0 for |a| < 2 pi).
  const double det = s * s + c * c;
  return {(s * start_T_end.x + c * start_T_end.y) / det, (-c * start_T_end.x + s * start_T_end.y) / det, a};
}

}  // namespace refloc
