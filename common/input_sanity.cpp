#include "common/input_sanity.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace refloc {

bool all_finite(std::initializer_list<double> values) { return all_finite(values.begin(), values.size()); }

bool all_finite(const double* values, std::size_t count) {
  return std::all_of(values, values + count, [](double v) { return std::isfinite(v); });
}

bool finite_within(double value, double lo, double hi) {
  return std::isfinite(value) && value >= lo && value <= hi;
}

bool finite_abs_at_most(double value, double max_abs) {
  return std::isfinite(value) && std::abs(value) <= max_abs;
}

bool is_usable_covariance(const Eigen::Matrix3d& covariance, double max_variance) {
  if (!covariance.allFinite()) return false;
  const double scale = covariance.cwiseAbs().maxCoeff();
  if (scale == 0.0) return true;  // exact knowledge is representable (a fixed initial pose)
  if ((covariance - covariance.transpose()).cwiseAbs().maxCoeff() > 1e-6 * scale) return false;
  if ((covariance.diagonal().array() > max_variance).any()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(covariance, Eigen::EigenvaluesOnly);
  return eigen.info() == Eigen::Success && eigen.eigenvalues().minCoeff() >= -1e-12 * scale;
}

}  // namespace refloc
