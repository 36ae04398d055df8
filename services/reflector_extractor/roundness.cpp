#include "reflector_extractor/roundness.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace refloc {

double paper_roundness_index(const std::vector<FitBeam>& beams, const Eigen::Vector2d& center, double radius,
                             int drop_points) {
  const int n = static_cast<int>(beams.size());
  const int begin = std::max(drop_points, 0);
  const int end = n - begin;
  if (end - begin < 1) return -1.0;
  double sum = 0.0;
  for (int i = begin; i < end; ++i) {
    sum += std::abs((beams[static_cast<size_t>(i)].point - center).norm() - radius);
  }
  return sum / static_cast<double>(end - begin);
}

RoundnessVerdict check_known_radius_roundness(const std::vector<FitBeam>& beams, const CircleFit& known_fit,
                                              const CircleFit* free_fit, double flat_chi2,
                                              const KnownRadiusRoundnessConfig& config) {
  const size_t n = beams.size();
  const double extent = lateral_extent(beams, known_fit.center);
  if (extent > 2.0 * known_fit.radius + config.lateral_margin) return RoundnessVerdict::kTooWide;
  if (n >= 2) {
    const Eigen::Vector2d& u0 = beams[0].direction;
    const Eigen::Vector2d& u1 = beams[1].direction;
    const double step = std::abs(std::atan2(u0.x() * u1.y() - u0.y() * u1.x(), u0.dot(u1)));
    const double beam_step_width = step * known_fit.center.norm();
    if (extent + beam_step_width < config.min_lateral_fraction * 2.0 * known_fit.radius) {
      return RoundnessVerdict::kTooNarrow;
    }
  }
  if (n > 2) {
    const double chi2 = std::min(known_fit.chi2, known_fit.central_ray_chi2);
    const double rms = std::sqrt(chi2 / static_cast<double>(n - 2));
    if (rms > config.max_rms_residual_sigmas) return RoundnessVerdict::kResidual;
    if (flat_chi2 >= 0.0 && chi2 - flat_chi2 > config.flat_chi2_margin) return RoundnessVerdict::kFlat;
  }
  if (free_fit != nullptr && static_cast<int>(n) >= config.min_beams_for_radius_check) {
    const double tolerance = std::max(config.radius_tolerance, config.radius_sigmas * free_fit->radius_sigma);
    if (std::abs(free_fit->radius - known_fit.radius) > tolerance) return RoundnessVerdict::kRadiusMismatch;
  }
  return RoundnessVerdict::kRound;
}

double lateral_extent(const std::vector<FitBeam>& beams, const Eigen::Vector2d& center) {
  const double range = center.norm();
  if (beams.size() < 2 || range <= 0.0) return 0.0;
  const Eigen::Vector2d across(-center.y() / range, center.x() / range);
  double lo = across.dot(beams.front().point);
  double hi = lo;
  for (const FitBeam& b : beams) {
    const double s = across.dot(b.point);
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  return hi - lo;
}

double flat_surface_chi2(const std::vector<FitBeam>& beams, double min_incidence_cos) {
  const size_t n = beams.size();
  if (n < 3) return 0.0;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const FitBeam& b : beams) mean += b.point;
  mean /= static_cast<double>(n);
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  for (const FitBeam& b : beams) scatter += (b.point - mean) * (b.point - mean).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(scatter);
  const Eigen::Vector2d normal = eigen.eigenvectors().col(0);  // smallest eigenvalue
  double chi2 = 0.0;
  for (const FitBeam& b : beams) {
    // Distance to the line along the beam, as for the circle's range residuals.
    const double cos_incidence = std::max(std::abs(normal.dot(b.direction)), min_incidence_cos);
    const double e = normal.dot(b.point - mean) / cos_incidence;
    chi2 += b.weight * e * e;
  }
  return chi2;
}

double mean_abs_range_residual(const std::vector<FitBeam>& beams, const CircleFit& fit,
                               const KnownRadiusFitConfig& config) {
  if (beams.empty()) return 0.0;
  double sum = 0.0;
  for (const FitBeam& b : beams) sum += std::abs(range_residual(b, fit.center, fit.radius, config));
  return sum / static_cast<double>(beams.size());
}

}  // namespace refloc
