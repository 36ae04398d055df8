#pragma once
// Is a reflector detection from the bus (REFLECTORS, or inside REFLECTOR_MATCHES) usable?
// The matcher and the solver both judge every detection they read with this one rule;
// the matcher forwards each detection as received, so every field must be finite.
// Header only: LCM-free, used by both services' libraries.

#include "common/input_sanity.hpp"
#include "common/input_stream_checks.hpp"
#include "common/reflector_detection.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {

struct DetectionBounds {
  static constexpr double kMaxRange_m = 200.0;  ///< as the extractor's scan bound
  /// Paper-mode algebraic fits of a few beams report thousands of m^2 (measured 6824 m^2);
  /// 1 km sigma bounds only what no fit gives.
  static constexpr double kMaxVariance_m2 = 1e6;
  static constexpr double kMaxAbsBearing = 6.3;  ///< [rad]
};

/// Finite fields; |centre| and range at most kMaxRange_m; |bearing| at most kMaxAbsBearing;
/// fitted radius >= 0 (only informational: the paper mode's free circle fit gives 10-20 m
/// for a 6 cm reflector's few beams); a covariance that is symmetric, positive
/// semi-definite and no variance above kMaxVariance_m2 (reason "covariance").
inline InputFault check_reflector_detection(const ReflectorDetection& d) {
  const Eigen::Matrix2d& c = d.covariance;
  if (!all_finite({d.laser_p_center.x(), d.laser_p_center.y(), c(0, 0), c(0, 1), c(1, 0), c(1, 1), d.range,
                   d.bearing, d.mean_rssi, d.roundness_m, d.fitted_radius_m}))
    return {"nonfinite", fmt::format("detection at ({}, {}) m with a non-finite field", d.laser_p_center.x(),
                                     d.laser_p_center.y())};
  if (!(d.laser_p_center.norm() <= DetectionBounds::kMaxRange_m) ||
      !finite_within(d.range, 0.0, DetectionBounds::kMaxRange_m) ||
      !finite_abs_at_most(d.bearing, DetectionBounds::kMaxAbsBearing) || !(d.fitted_radius_m >= 0.0))
    return {"out_of_bounds",
            fmt::format("detection at ({}, {}) m, range {} m, bearing {} rad, radius {} m",
                        d.laser_p_center.x(), d.laser_p_center.y(), d.range, d.bearing, d.fitted_radius_m)};
  Eigen::Matrix3d embedded = Eigen::Matrix3d::Zero();  // a zero third axis leaves the 2x2's eigenvalues
  embedded.topLeftCorner<2, 2>() = c;
  if (!is_usable_covariance(embedded, DetectionBounds::kMaxVariance_m2))
    return {"covariance",
            fmt::format("detection covariance [{}, {}; {}, {}] m^2", c(0, 0), c(0, 1), c(1, 0), c(1, 1))};
  return {};
}

/// The first unusable detection decides (the whole message is rejected: the detections of
/// one scan come from one publisher, and one bad one means it is broken).
inline InputFault check_reflector_detections(const std::vector<ReflectorDetection>& detections) {
  for (size_t i = 0; i < detections.size(); ++i) {
    InputFault f = check_reflector_detection(detections[i]);
    if (f) {
      f.detail = fmt::format("#{}: {}", i, f.detail);
      return f;
    }
  }
  return {};
}

/// The bounds of a match's map side.
struct MatchBounds {
  static constexpr double kMaxAbsCoordinate_m = 1e4;  ///< no site is 10 km across
  static constexpr double kMaxRadius_m = 1.0;         ///< reflector cylinders are centimetres wide
};

/// REFLECTOR_MATCHES as its readers (pose_solver, pose_fusion) judge it: every detection
/// usable (check_reflector_detection) and every map position finite within
/// kMaxAbsCoordinate_m with 0 < radius <= kMaxRadius_m; the first failure decides.
inline InputFault check_matches(const std::vector<ReflectorDetection>& detections,
                                const std::vector<ReflectorMatch>& matches) {
  if (InputFault f = check_reflector_detections(detections)) return f;
  for (size_t i = 0; i < matches.size(); ++i) {
    const ReflectorMatch& m = matches[i];
    if (!all_finite({m.map_p_center.x(), m.map_p_center.y(), m.map_radius}))
      return {"nonfinite", fmt::format("match #{}: map reflector with a non-finite field", i)};
    if (!finite_abs_at_most(m.map_p_center.x(), MatchBounds::kMaxAbsCoordinate_m) ||
        !finite_abs_at_most(m.map_p_center.y(), MatchBounds::kMaxAbsCoordinate_m) ||
        !(m.map_radius > 0.0 && m.map_radius <= MatchBounds::kMaxRadius_m) || m.detection_index < 0 ||
        m.detection_index >= static_cast<int>(detections.size()))
      return {"out_of_bounds", fmt::format("match #{}: map reflector {} at ({}, {}) m, radius {} m", i,
                                           m.map_id, m.map_p_center.x(), m.map_p_center.y(), m.map_radius)};
  }
  return {};
}

}  // namespace refloc
