#include "common/se2.hpp"

#include <cmath>

namespace refloc {

double wrap_angle(double angle_rad) {
  double wrapped = std::remainder(angle_rad, 2.0 * M_PI);  // in [-pi, pi]
  if (wrapped <= -M_PI) wrapped += 2.0 * M_PI;
  return wrapped;
}

double angle_diff(double a_rad, double b_rad) { return wrap_angle(a_rad - b_rad); }

double circular_mean(const std::vector<double>& angles_rad) {
  double s = 0.0, c = 0.0;
  for (double a : angles_rad) {
    s += std::sin(a);
    c += std::cos(a);
  }
  if (s == 0.0 && c == 0.0) return 0.0;
  return std::atan2(s, c);
}

double circular_mean(const std::vector<double>& angles_rad, const std::vector<double>& weights) {
  double s = 0.0, c = 0.0;
  for (size_t i = 0; i < angles_rad.size() && i < weights.size(); ++i) {
    s += weights[i] * std::sin(angles_rad[i]);
    c += weights[i] * std::cos(angles_rad[i]);
  }
  if (s == 0.0 && c == 0.0) return 0.0;
  return std::atan2(s, c);
}

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

}  // namespace refloc
