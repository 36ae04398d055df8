#pragma once
// Angle math: degree conversion and the one wrap convention, (-pi, pi], every
// heading in refloc is reduced by.

#include <cmath>
#include <vector>

namespace refloc {

/// Radians in one degree. Inside refloc angles are radians; degrees appear only
/// in config keys and reports whose name ends in _deg.
constexpr double kDegToRad = M_PI / 180.0;

/// [deg] -> [rad].
constexpr double deg_to_rad(double angle_deg) { return angle_deg * kDegToRad; }

/// [rad] -> [deg] (the exact inverse arithmetic of deg_to_rad, so config defaults round-trip).
constexpr double rad_to_deg(double angle_rad) { return angle_rad / kDegToRad; }

/// Wrap an angle to (-pi, pi] [rad].
double wrap_angle(double angle_rad);

/// Smallest signed difference a - b, wrapped to (-pi, pi] [rad].
double angle_diff(double a_rad, double b_rad);

/// Mean direction of angles (atan2 of summed unit vectors) [rad]; 0 for an empty input.
double circular_mean(const std::vector<double>& angles_rad);

/// Weighted circular mean [rad]; weights must be >= 0.
double circular_mean(const std::vector<double>& angles_rad, const std::vector<double>& weights);

}  // namespace refloc
