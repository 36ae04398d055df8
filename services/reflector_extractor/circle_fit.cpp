// The circle fits and their one residual model (central ray, beam spot, wall behind, second-order
// bias); longer than 300 lines because the fits and the model they share read best side by side.
#include "reflector_extractor/circle_fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

bool is_positive_definite(const Eigen::Matrix2d& m) {
  return m(0, 0) > 0.0 && m(1, 1) > 0.0 && m.determinant() > 0.0;
}

// Gauss-Legendre nodes and weights on [-1, 1], 8 points.
constexpr std::array<double, 8> kGaussNode = {-0.9602898564975363, -0.7966664774136267, -0.5255324099163290,
                                              -0.1834346424956498, 0.1834346424956498,  0.5255324099163290,
                                              0.7966664774136267,  0.9602898564975363};
constexpr std::array<double, 8> kGaussWeight = {0.1012285362903763, 0.2223810344533745, 0.3137066458778873,
                                                0.3626837833783620, 0.3626837833783620, 0.3137066458778873,
                                                0.2223810344533745, 0.1012285362903763};

// Spot-weighted mean range of the part of a beam's spot on a circle whose centre lies at
// (along, across) in the beam's frame; NaN when the spot misses it. The spot's rays are taken
// parallel (their divergence changes a range by < 0.3 mm at 10 m); a ray at lateral offset y has
// the Gaussian weight exp(-2 y^2 / h^2) (1/e^2 at the rim h) and meets the circle at
// along - sqrt(r^2 - (y - across)^2). Integrated over the chord angle phi, y = across + r sin(phi),
// the integrand is smooth, so the mean moves smoothly with the centre and Gauss-Newton converges.
// With a background (a finite background_range), the rest of the spot's weight lands there with
// background_ratio of the reflector's energy per unit weight, and the echo is the energy-weighted
// mean of the two ranges.
double spot_mean_range(double along, double across, double radius, double half_width,
                       double background_range = std::numeric_limits<double>::quiet_NaN(),
                       double background_ratio = 0.0) {
  const double lo = std::max(-half_width, across - radius);
  const double hi = std::min(half_width, across + radius);
  if (!(hi > lo)) return std::numeric_limits<double>::quiet_NaN();
  const double phi_lo = std::asin(std::clamp((lo - across) / radius, -1.0, 1.0));
  const double phi_hi = std::asin(std::clamp((hi - across) / radius, -1.0, 1.0));
  const double mid = 0.5 * (phi_hi + phi_lo);
  const double half = 0.5 * (phi_hi - phi_lo);
  const double inv_h2 = 1.0 / (half_width * half_width);
  double depth = 0.0;   // integral of w * cos^2: the mean depth behind the centre's front
  double weight = 0.0;  // integral of w * cos (dy = r cos dphi)
  for (size_t k = 0; k < kGaussNode.size(); ++k) {
    const double phi = mid + half * kGaussNode[k];
    const double y = across + radius * std::sin(phi);
    const double c = std::cos(phi);
    const double w = kGaussWeight[k] * std::exp(-2.0 * y * y * inv_h2) * c;
    weight += w;
    depth += w * c;
  }
  if (!(weight > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  const double on_cylinder = along - radius * depth / weight;
  if (!std::isfinite(background_range) || !(background_ratio > 0.0)) return on_cylinder;
  // The spot's whole weight, the integral of exp(-2 y^2 / h^2) over [-h, h], against the part on
  // the circle (the sum above is that integral over phi without its factor r * half).
  const double whole = half_width * std::sqrt(M_PI / 2.0) * std::erf(std::sqrt(2.0));
  const double covered = std::min(radius * half * weight, whole);
  const double beside = background_ratio * (whole - covered);
  return (covered * on_cylinder + beside * background_range) / (covered + beside);
}

// The second-order bias of the least-squares centre (Box 1971), along `axis` only: each beam's
// predicted range is on average half its curvature times the centre's covariance longer than at
// the centre, which the fit answers by moving the centre; the move that undoes it. The Hessian of
// each beam's prediction comes from central differences of its Jacobian.
double second_order_bias_along(const std::vector<FitBeam>& beams, double radius,
                               const KnownRadiusFitConfig& config, const Eigen::Vector2d& center,
                               const Eigen::Vector2d& axis) {
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  for (const FitBeam& b : beams) {
    Eigen::Vector2d jac;
    range_residual(b, center, radius, config, &jac);
    information += b.weight * jac * jac.transpose();
  }
  if (!(information.determinant() > 1e-12 * information.trace() * information.trace())) return 0.0;
  const Eigen::Matrix2d covariance = information.inverse();
  constexpr double kStep = 1e-4;  // [m]: well inside the model's smooth part, far above its 1e-6 steps
  Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
  for (const FitBeam& b : beams) {
    Eigen::Vector2d jac;
    range_residual(b, center, radius, config, &jac);
    Eigen::Matrix2d hessian;
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d plus, minus;
      range_residual(b, center + kStep * Eigen::Vector2d::Unit(k), radius, config, &plus);
      range_residual(b, center - kStep * Eigen::Vector2d::Unit(k), radius, config, &minus);
      hessian.col(k) = (plus - minus) / (2.0 * kStep);
    }
    const double mean_excess = 0.5 * (0.5 * (hessian + hessian.transpose()) * covariance).trace();
    if (std::isfinite(mean_excess)) gradient += b.weight * jac * mean_excess;
  }
  const Eigen::Vector2d bias = -covariance * gradient;
  return bias.dot(axis);
}

// Gauss-Newton on the centre from `center`; the number of iterations, -1 when a step is not finite.
int gauss_newton_centre(const std::vector<FitBeam>& beams, double radius, const KnownRadiusFitConfig& config,
                        Eigen::Vector2d& center) {
  int iteration = 0;
  for (; iteration < config.max_iterations; ++iteration) {
    Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
    Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
    for (const FitBeam& b : beams) {
      Eigen::Vector2d jac;
      const double e = range_residual(b, center, radius, config, &jac);
      information += b.weight * jac * jac.transpose();
      gradient += b.weight * jac * e;
    }
    // A whisker of damping keeps one-beam clusters (rank 1) solvable.
    const Eigen::Matrix2d damped =
        information + Eigen::Matrix2d::Identity() * (1e-9 * information.trace() + 1e-12);
    Eigen::Vector2d step = -damped.ldlt().solve(gradient);
    if (!step.allFinite()) return -1;
    const double step_norm = step.norm();
    if (step_norm > radius) step *= radius / step_norm;  // keep Gauss-Newton from jumping away
    center += step;
    if (step_norm < config.step_tolerance) return iteration + 1;
  }
  return iteration;
}

}  // namespace

double range_residual(const FitBeam& beam, const Eigen::Vector2d& center, double radius,
                      const KnownRadiusFitConfig& config, Eigen::Vector2d* d_center, double* d_radius) {
  if (config.spot.applies()) {
    const Eigen::Vector2d lateral(-beam.direction.y(), beam.direction.x());
    const Eigen::Vector2d origin_to_center = center - (beam.point - beam.range * beam.direction);
    const double along = origin_to_center.dot(beam.direction);
    const double across = origin_to_center.dot(lateral);
    const double half_width =
        0.5 * config.spot.exit_diameter_m + std::max(along, 0.0) * std::tan(0.5 * config.spot.divergence_rad);
    const bool background = config.spot.background && std::isfinite(beam.background_range);
    const double bg_range = background ? beam.background_range : std::numeric_limits<double>::quiet_NaN();
    const double bg_ratio = background ? beam.background_energy_ratio : 0.0;
    const double predicted = spot_mean_range(along, across, radius, half_width, bg_range, bg_ratio);
    if (std::isfinite(predicted) && half_width > 0.0) {
      // d/d along = 1 on the cylinder alone (the background's share stays behind); across, radius
      // and, with a background, along by forward differences (1e-6 m moves the chord's ends
      // smoothly; the analytic form has boundary terms at the spot's rim).
      constexpr double kStep = 1e-6;
      if (d_center != nullptr) {
        const double moved = spot_mean_range(along, across + kStep, radius, half_width, bg_range, bg_ratio);
        const double d_across = std::isfinite(moved) ? (moved - predicted) / kStep : 0.0;
        double d_along = 1.0;
        if (background) {
          const double pushed =
              spot_mean_range(along + kStep, across, radius, half_width, bg_range, bg_ratio);
          d_along = std::isfinite(pushed) ? (pushed - predicted) / kStep : 1.0;
        }
        *d_center = d_along * beam.direction + d_across * lateral;
      }
      if (d_radius != nullptr) {
        const double grown = spot_mean_range(along, across, radius + kStep, half_width, bg_range, bg_ratio);
        *d_radius = std::isfinite(grown) ? (grown - predicted) / kStep : -1.0;
      }
      return predicted - beam.range;
    }
  }
  const Eigen::Vector2d center_to_point = beam.point - center;
  const double distance = std::max(center_to_point.norm(), 1e-9);
  const Eigen::Vector2d normal = center_to_point / distance;
  // Range error ~ geometric error / cos(incidence): exactly the linearised ray-circle
  // intersection, see the derivation in the extractor README.
  const double cos_incidence = std::max(-beam.direction.dot(normal), config.min_incidence_cos);
  if (d_center != nullptr) *d_center = -normal / cos_incidence;
  if (d_radius != nullptr) *d_radius = -1.0 / cos_incidence;
  return (distance - radius) / cos_incidence;
}

bool fit_circle_algebraic(const std::vector<FitBeam>& beams, double point_sigma, CircleFit& out) {
  const size_t n = beams.size();
  if (n < 3) return false;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const FitBeam& b : beams) mean += b.point;
  mean /= static_cast<double>(n);
  // Kasa: minimise sum (x^2 + y^2 + D x + E y + F)^2 in centred coordinates.
  Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rhs = Eigen::Vector3d::Zero();
  for (const FitBeam& b : beams) {
    const Eigen::Vector2d q = b.point - mean;
    const Eigen::Vector3d row(q.x(), q.y(), 1.0);
    normal_matrix += row * row.transpose();
    rhs -= row * q.squaredNorm();
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(normal_matrix);
  if (lu.rank() < 3) return false;
  const Eigen::Vector3d def = lu.solve(rhs);
  const Eigen::Vector2d local_center(-0.5 * def.x(), -0.5 * def.y());
  const double r2 = local_center.squaredNorm() - def.z();
  if (!(r2 > 0.0) || !std::isfinite(r2)) return false;
  out.center = local_center + mean;
  out.radius = std::sqrt(r2);
  // First-order covariance of (centre, radius) under isotropic point noise.
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  out.chi2 = 0.0;
  for (const FitBeam& b : beams) {
    const Eigen::Vector2d d = b.point - out.center;
    const double dist = std::max(d.norm(), 1e-9);
    const Eigen::Vector3d jac(-d.x() / dist, -d.y() / dist, -1.0);
    information += jac * jac.transpose();
    const double e = dist - out.radius;
    out.chi2 += e * e / (point_sigma * point_sigma);
  }
  // Points on a near-straight arc leave the information (numerically) singular: no fit.
  const Eigen::FullPivLU<Eigen::Matrix3d> information_lu(information);
  if (information_lu.rank() < 3) return false;
  const Eigen::Matrix3d cov = information_lu.inverse() * point_sigma * point_sigma;
  out.central_ray_chi2 = out.chi2;
  out.covariance = cov.topLeftCorner<2, 2>();
  out.radius_sigma = std::sqrt(std::max(cov(2, 2), 0.0));
  out.iterations = 0;
  return out.center.allFinite() && out.covariance.allFinite() && is_positive_definite(out.covariance);
}

bool fit_circle_known_radius(const std::vector<FitBeam>& beams, double radius,
                             const KnownRadiusFitConfig& config, CircleFit& out) {
  if (beams.empty()) return false;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const FitBeam& b : beams) mean += b.point;
  mean /= static_cast<double>(beams.size());
  // The visible surface faces the sensor, so the centre is one radius farther away.
  Eigen::Vector2d center = mean + radius * mean.normalized();
  int iteration = 0;
  double central_ray_chi2 = -1.0;
  // The central-ray model: the first fit when the spot is modelled, and the covariance's.
  KnownRadiusFitConfig central_ray = config;
  central_ray.spot.enabled = false;
  if (config.spot.applies()) {
    // First the central-ray fit, whose cost is smooth everywhere: it places the centre.
    const int first = gauss_newton_centre(beams, radius, central_ray, center);
    if (first < 0) return false;
    iteration += first;
    const Eigen::Vector2d central_ray_center = center;
    central_ray_chi2 = 0.0;
    for (const FitBeam& b : beams) {
      const double e = range_residual(b, center, radius, central_ray);
      central_ray_chi2 += b.weight * e * e;
    }
    // Then the spot model, from there, of which only the move along the line of sight is kept:
    // the spot's effect is a systematic range one (the face's mean depth under the spot), while
    // the model's steep flank beams turn range noise into lateral error (lateral RMS +15 % at
    // 2-6 m when the whole refined centre was kept). A move larger than a quarter radius (the
    // spot moves a centre by ~12 mm at most) fell into one of the model's false minima, ~0.1 m
    // beside the reflector, where a grazed spot predicts any range: the central-ray fit stays.
    // Measured against a 1-D fit along the line of sight (3x cheaper): the same static bias, but
    // the demo-hall survey's map scale +524 ppm instead of +238 ppm (wall-mounted reflectors,
    // whose spot also catches the wall behind).
    const int refined = gauss_newton_centre(beams, radius, config, center);
    const Eigen::Vector2d line_of_sight = central_ray_center.normalized();
    const double along = refined < 0 ? 0.0 : (center - central_ray_center).dot(line_of_sight);
    center = refined < 0 || (center - central_ray_center).norm() > 0.25 * radius
                 ? central_ray_center
                 : Eigen::Vector2d(central_ray_center + along * line_of_sight);
    iteration += std::max(refined, 0);
  } else {
    const int fitted = gauss_newton_centre(beams, radius, config, center);
    if (fitted < 0) return false;
    iteration += fitted;
  }
  if (config.second_order_bias_correction && beams.size() >= 2) {
    const Eigen::Vector2d line_of_sight = center.normalized();
    const double bias = second_order_bias_along(beams, radius, config, center, line_of_sight);
    // A bias beyond a quarter radius is no second-order effect: a degenerate geometry, left alone.
    if (std::isfinite(bias) && std::abs(bias) < 0.25 * radius) center -= bias * line_of_sight;
  }
  // The covariance is the central-ray fit's: its lateral estimate is the one kept, and the
  // spot's correction along the line of sight is a systematic one (NEES over 0.5-6 m stays
  // 1.5-2.1 as before the spot model; with the spot model's own information it fell to 1.2).
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  out.chi2 = 0.0;
  for (const FitBeam& b : beams) {
    Eigen::Vector2d jac;
    const double central_ray_e = range_residual(b, center, radius, central_ray, &jac);
    information += b.weight * jac * jac.transpose();
    const double e = config.spot.applies() ? range_residual(b, center, radius, config) : central_ray_e;
    out.chi2 += b.weight * e * e;
  }
  out.central_ray_chi2 = central_ray_chi2 >= 0.0 ? central_ray_chi2 : out.chi2;
  out.center = center;
  out.radius = radius;
  out.radius_sigma = 0.0;
  out.iterations = iteration;
  // A rank-deficient information (one beam) leaves the tangential direction unknown:
  // report a large, not an infinite, variance there.
  const Eigen::Matrix2d regularised =
      information + Eigen::Matrix2d::Identity() * 1e-6 * std::max(information.trace(), 1.0);
  out.covariance = information.determinant() > 1e-12 * information.trace() * information.trace()
                       ? Eigen::Matrix2d(information.inverse())
                       : Eigen::Matrix2d(regularised.inverse());
  return out.center.allFinite() && out.covariance.allFinite() && is_positive_definite(out.covariance);
}

bool fit_circle_free_radius(const std::vector<FitBeam>& beams, const Eigen::Vector2d& center, double radius,
                            const KnownRadiusFitConfig& config, CircleFit& out) {
  if (beams.size() < 4) return false;
  Eigen::Vector3d params(center.x(), center.y(), radius);
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  int iteration = 0;
  for (; iteration < config.max_iterations; ++iteration) {
    information.setZero();
    Eigen::Vector3d gradient = Eigen::Vector3d::Zero();
    for (const FitBeam& b : beams) {
      Eigen::Vector2d jc;
      double jr = 0.0;
      const double e = range_residual(b, params.head<2>(), params.z(), config, &jc, &jr);
      const Eigen::Vector3d jac(jc.x(), jc.y(), jr);
      information += b.weight * jac * jac.transpose();
      gradient += b.weight * jac * e;
    }
    const Eigen::Matrix3d damped =
        information + Eigen::Matrix3d::Identity() * (1e-9 * information.trace() + 1e-12);
    Eigen::Vector3d step = -damped.ldlt().solve(gradient);
    if (!step.allFinite()) return false;
    params += step;
    if (params.z() <= 0.0) params.z() = 1e-3;  // a radius stays a radius
    if (step.norm() < config.step_tolerance) {
      ++iteration;
      break;
    }
  }
  out.chi2 = 0.0;
  information.setZero();
  for (const FitBeam& b : beams) {
    Eigen::Vector2d jc;
    double jr = 0.0;
    const double e = range_residual(b, params.head<2>(), params.z(), config, &jc, &jr);
    const Eigen::Vector3d jac(jc.x(), jc.y(), jr);
    information += b.weight * jac * jac.transpose();
    out.chi2 += b.weight * e * e;
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(information);
  if (lu.rank() < 3) return false;
  const Eigen::Matrix3d cov = lu.inverse();
  out.central_ray_chi2 = out.chi2;
  out.center = params.head<2>();
  out.radius = params.z();
  out.covariance = cov.topLeftCorner<2, 2>();
  out.radius_sigma = std::sqrt(std::max(cov(2, 2), 0.0));
  out.iterations = iteration;
  return params.allFinite() && cov.allFinite();
}

}  // namespace refloc
