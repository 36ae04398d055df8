#pragma once
// What pose_fusion believes of the numbers in an ODOMETRY or LASER_POSE message
// before they reach the filter. A message that fails is skipped as a whole and
// counted as rejected_<input>_<reason>; every check is written so that NaN fails it.
//
// Bounds (documented in services/pose_fusion/README.md): positions within
// kMaxAbsPosition_m of the frame's origin, headings within kMaxAbsHeading_rad (both
// streams publish wrapped headings; anything beyond is a broken publisher), odometry
// distance within [0, kMaxDistance_m], its twist within kMaxAbsSpeed_m_s and
// kMaxAbsYawRate_rad_s (far beyond any wheeled robot); a fix's covariance symmetric positive
// semi-definite with a positive diagonal no larger than kMaxFixVariance (a "fix"
// less certain than 1 m / 1 rad carries no information the filter should take, and
// re-initialising from it would publish an OK pose that is not one).

#include "common/odometry_sample.hpp"
#include "pose_fusion/laser_fix_input.hpp"

namespace refloc {

/// Why a message's values were refused; kNone: usable. to_string gives the counter's reason word.
enum class InputProblem { kNone, kNonFinite, kOutOfBounds, kCovariance };
const char* to_string(InputProblem problem);

constexpr double kMaxAbsPosition_m = 1e5;
constexpr double kMaxAbsHeading_rad = 6.2832;  ///< 2 pi, rounded up
constexpr double kMaxDistance_m = 1e9;
constexpr double kMaxAbsSpeed_m_s = 50.0;
constexpr double kMaxAbsYawRate_rad_s = 50.0;
constexpr double kMaxFixVariance = 1.0;  ///< [m^2] and [rad^2]

/// The values of one ODOMETRY message (pose, distance, twist: fusion does not use the
/// twist, but a message with an absurd one is broken as a whole).
InputProblem check_odometry_values(const OdometrySample& sample);

/// The values of one LASER_POSE message that carries a pose (status OK or DEGRADED).
InputProblem check_fix_values(const LaserFixInput& input);

}  // namespace refloc
