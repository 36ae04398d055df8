#pragma once
// Honest uncertainty as a measured property: the normalized estimation error squared
// (NEES) of published fixes against the truth. A fix whose covariance is honest has a
// position NEES (2 dof) of mean 2, 1 % of them beyond 9.21 (its 99 % ellipse), and a
// heading NEES (1 dof) of mean 1, 1 % beyond 6.63. A mean well above says the covariance
// is too small (over-confident), well below too large; biased ranges show as both a
// higher mean and a fat tail.

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <optional>

namespace refloc {

constexpr double kChiSquare2Dof99 = 9.21034;  ///< 99 % quantile of chi-square, 2 dof
constexpr double kChiSquare1Dof99 = 6.63490;  ///< 99 % quantile of chi-square, 1 dof

/// e^T P^-1 e of a position error [m] with its covariance [m^2]; empty when P is not
/// positive definite or anything is not finite.
std::optional<double> position_nees(const Eigen::Vector2d& error, const Eigen::Matrix2d& covariance);
/// e^2 / var of a heading error [rad] with its variance [rad^2]; empty when var <= 0 or not finite.
std::optional<double> heading_nees(double error, double variance);

struct ConsistencySummary {
  int fixes = 0;                     ///< fixes added
  int unusable_covariances = 0;      ///< of them, with no NEES (covariance not positive definite)
  double position_nees_mean = 0.0;   ///< expected 2 when honest
  double position_outside_99 = 0.0;  ///< share with NEES > kChiSquare2Dof99, expected 0.01
  double heading_nees_mean = 0.0;    ///< expected 1 when honest
  double heading_outside_99 = 0.0;   ///< share with NEES > kChiSquare1Dof99, expected 0.01
};

/// Adds fixes one by one; the means and shares are over the fixes with usable covariances.
class ConsistencyAccumulator {
 public:
  /// error = estimate - truth: (x [m], y [m], heading [rad, wrapped]); covariance of (x, y, heading).
  void add(const Eigen::Vector3d& error, const Eigen::Matrix3d& covariance);
  ConsistencySummary summary() const;

 private:
  ConsistencySummary sum_;  ///< counts, with the means and shares as sums until summary()
  int position_count_ = 0;
  int heading_count_ = 0;
};

/// The summary as JSON, one form for every tool (refloc-eval's studies, refloc-mission):
/// nees_fixes, unusable_covariances, position_nees_mean, position_outside_99_percent (a share,
/// 0..1), heading_nees_mean, heading_outside_99_percent.
nlohmann::json consistency_json(const ConsistencySummary& s);

}  // namespace refloc
