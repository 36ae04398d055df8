#pragma once
// Checks every service runs on the numbers it consumes before they reach a filter, a
// gate or a published message. Each returns false for NaN and infinity, so a caller
// that writes `if (!plausible(...)) reject;` can never let a non-finite value through
// the way `if (x > limit) reject;` does.

#include <Eigen/Core>

#include <cstddef>
#include <initializer_list>

namespace refloc {

/// True when every value is finite.
bool all_finite(std::initializer_list<double> values);
bool all_finite(const double* values, std::size_t count);

/// True when value is finite and lo <= value <= hi.
bool finite_within(double value, double lo, double hi);

/// True when |value| is finite and at most max_abs.
bool finite_abs_at_most(double value, double max_abs);

/// A covariance a filter can use: finite, symmetric (relative 1e-6), positive
/// semi-definite (eigenvalues >= -1e-12 of the largest), and no variance above
/// max_variance (in the matrix's own units; e.g. m^2 for position).
bool is_usable_covariance(const Eigen::Matrix3d& covariance, double max_variance);

}  // namespace refloc
