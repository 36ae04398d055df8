#pragma once
// What LASER_POSE says about one scan, from the matcher's verdict and the solver's
// solution. The matcher's doubt wins: an AMBIGUOUS or LOST association gives no pose,
// whatever a solver would make of it; without a pose the covariance is 1e6 I, which no
// consumer mistakes for information.

#include "pose_solver/pose_solution.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <cstdint>

namespace refloc {

/// The matcher's status as REFLECTOR_MATCHES carries it (reflector_matches_t::STATUS_*).
enum class MatchVerdict { kOk, kAmbiguous, kLost };

/// Same meaning as pose2d_t::STATUS_OK / DEGRADED / LOST / AMBIGUOUS.
enum class LaserFixStatus { kOk, kDegraded, kLost, kAmbiguous };

struct LaserFix {
  int64_t utime = 0;  ///< the scan's [us]
  LaserFixStatus status = LaserFixStatus::kLost;
  bool has_pose = false;  ///< OK or DEGRADED: map_T_robot and covariance mean something
  Pose2 map_T_robot;      ///< zero without a pose
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity() * 1e6;  ///< [m^2, m rad, rad^2]
  int reflectors_used = 0;
  double residual = 0.0;    ///< RMS range residual [m]; 0 without a pose
  int outlier_matches = 0;  ///< matches the solver dropped
  /// The solver's pose or covariance was not finite or not a usable covariance (variance
  /// above kMaxFixVariance, not symmetric PSD): no pose, status LOST, never published as is.
  bool unusable_solution = false;
  /// The range offset b this fix took off (PoseSolution's); with a pose only.
  RangeBiasUse range_bias_use = RangeBiasUse::kNoSolution;
  double range_bias = 0.0;        ///< [m]
  double range_bias_sigma = 0.0;  ///< [m]

  /// Calls bump(name, increment) for each heartbeat counter this fix touches.
  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    if (status == LaserFixStatus::kDegraded) bump("degraded_fixes", 1);
    if (status == LaserFixStatus::kLost) bump("lost_fixes", 1);
    if (status == LaserFixStatus::kAmbiguous) bump("ambiguous_fixes", 1);
    if (outlier_matches > 0) bump("outlier_matches", outlier_matches);
    if (unusable_solution) bump("unusable_solutions", 1);
    if (range_bias_unestimable()) bump("range_bias_unestimable_fixes", 1);
  }
  /// A pose whose scan could not estimate b although estimation is on: b held, covariance inflated.
  bool range_bias_unestimable() const {
    return has_pose &&
           (range_bias_use == RangeBiasUse::kFewReflectors || range_bias_use == RangeBiasUse::kWeakGeometry);
  }
  /// Why b was not estimated, for the heartbeat detail of an OK state; empty when it was.
  const char* range_bias_detail() const {
    if (!has_pose) return "";
    if (range_bias_use == RangeBiasUse::kFewReflectors)
      return "range bias not estimable (too few reflectors): held, its sigma in the covariance";
    if (range_bias_use == RangeBiasUse::kWeakGeometry)
      return "range bias not estimable (reflectors not spread enough): held, its sigma in the covariance";
    return "";
  }
  /// The heartbeat state after this fix: OK, else DEGRADED with this detail.
  bool ok() const { return status == LaserFixStatus::kOk; }
  const char* degraded_detail() const {
    if (unusable_solution) return "last solution not finite or covariance unusable";
    return has_pose ? "last fix DEGRADED" : "no fix from the last scan";
  }
};

/// The largest variance a published fix may carry [m^2, rad^2]: the no-pose covariance's.
constexpr double kMaxFixVariance = 1e6;

/// LASER_POSE for a scan at utime [us]: solution is read only when verdict is kOk;
/// matches = the number of matches the solver was given.
LaserFix make_laser_fix(int64_t utime, MatchVerdict verdict, const PoseSolution& solution, int matches);

}  // namespace refloc
