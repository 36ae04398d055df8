#include "reflector_extractor/circle_fit.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>

namespace refloc {
namespace {

bool is_positive_definite(const Eigen::Matrix2d& m) {
  return m(0, 0) > 0.0 && m(1, 1) > 0.0 && m.determinant() > 0.0;
}

}  // namespace

double range_residual(const FitBeam& beam, const Eigen::Vector2d& center, double radius,
                      double min_incidence_cos, Eigen::Vector2d* d_center, double* d_radius) {
  const Eigen::Vector2d center_to_point = beam.point - center;
  const double distance = std::max(center_to_point.norm(), 1e-9);
  const Eigen::Vector2d normal = center_to_point / distance;
  // Range error ~ geometric error / cos(incidence): exactly the linearised ray-circle
  // intersection, see the derivation in the extractor README.
  const double cos_incidence = std::max(-beam.direction.dot(normal), min_incidence_cos);
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
  Eigen::Matrix2d information = Eigen::Matrix2d::Zero();
  int iteration = 0;
  for (; iteration < config.max_iterations; ++iteration) {
    information.setZero();
    Eigen::Vector2d gradient = Eigen::Vector2d::Zero();
    for (const FitBeam& b : beams) {
      Eigen::Vector2d jac;
      const double e = range_residual(b, center, radius, config.min_incidence_cos, &jac);
      information += b.weight * jac * jac.transpose();
      gradient += b.weight * jac * e;
    }
    // A whisker of damping keeps one-beam clusters (rank 1) solvable.
    const Eigen::Matrix2d damped =
        information + Eigen::Matrix2d::Identity() * (1e-9 * information.trace() + 1e-12);
    Eigen::Vector2d step = -damped.ldlt().solve(gradient);
    if (!step.allFinite()) return false;
    const double step_norm = step.norm();
    if (step_norm > radius) step *= radius / step_norm;  // keep Gauss-Newton from jumping away
    center += step;
    if (step_norm < config.step_tolerance) {
      ++iteration;
      break;
    }
  }
  information.setZero();
  out.chi2 = 0.0;
  for (const FitBeam& b : beams) {
    Eigen::Vector2d jac;
    const double e = range_residual(b, center, radius, config.min_incidence_cos, &jac);
    information += b.weight * jac * jac.transpose();
    out.chi2 += b.weight * e * e;
  }
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
      const double e = range_residual(b, params.head<2>(), params.z(), config.min_incidence_cos, &jc, &jr);
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
    const double e = range_residual(b, params.head<2>(), params.z(), config.min_incidence_cos, &jc, &jr);
    const Eigen::Vector3d jac(jc.x(), jc.y(), jr);
    information += b.weight * jac * jac.transpose();
    out.chi2 += b.weight * e * e;
  }
  const Eigen::FullPivLU<Eigen::Matrix3d> lu(information);
  if (lu.rank() < 3) return false;
  const Eigen::Matrix3d cov = lu.inverse();
  out.center = params.head<2>();
  out.radius = params.z();
  out.covariance = cov.topLeftCorner<2, 2>();
  out.radius_sigma = std::sqrt(std::max(cov(2, 2), 0.0));
  out.iterations = iteration;
  return params.allFinite() && cov.allFinite();
}

}  // namespace refloc
