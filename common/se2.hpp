#pragma once
// SE(2) geometry. Frame naming follows Sophus: a_T_b takes points in frame b
// into frame a, a_p_x is point x expressed in frame a.

#include <Eigen/Core>
#include <vector>

namespace refloc {

/// Wrap an angle to (-pi, pi] [rad].
double wrap_angle(double angle_rad);

/// Smallest signed difference a - b, wrapped to (-pi, pi] [rad].
double angle_diff(double a_rad, double b_rad);

/// Mean direction of angles (atan2 of summed unit vectors) [rad]; 0 for an empty input.
double circular_mean(const std::vector<double>& angles_rad);

/// Weighted circular mean [rad]; weights must be >= 0.
double circular_mean(const std::vector<double>& angles_rad, const std::vector<double>& weights);

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

}  // namespace refloc
