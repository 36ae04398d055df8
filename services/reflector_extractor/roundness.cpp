#include "reflector_extractor/roundness.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

double paper_roundness_index(const std::vector<FitBeam>& beams, const Eigen::Vector2d& center,
                             double radius, int drop_points) {
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
                                              const CircleFit* free_fit, const KnownRadiusRoundnessConfig& config) {
  const size_t n = beams.size();
  if (n >= 2) {
    const double chord = (beams.front().point - beams.back().point).norm();
    if (chord > 2.0 * known_fit.radius + config.chord_margin) return RoundnessVerdict::kTooWide;
  }
  if (n > 2) {
    const double rms = std::sqrt(known_fit.chi2 / static_cast<double>(n - 2));
    if (rms > config.max_rms_residual_sigmas) return RoundnessVerdict::kResidual;
  }
  if (free_fit != nullptr && static_cast<int>(n) >= config.min_beams_for_radius_check) {
    const double tolerance = std::max(config.radius_tolerance, config.radius_sigmas * free_fit->radius_sigma);
    if (std::abs(free_fit->radius - known_fit.radius) > tolerance) return RoundnessVerdict::kRadiusMismatch;
  }
  return RoundnessVerdict::kRound;
}

double mean_abs_range_residual(const std::vector<FitBeam>& beams, const CircleFit& fit, double min_incidence_cos) {
  if (beams.empty()) return 0.0;
  double sum = 0.0;
  for (const FitBeam& b : beams) sum += std::abs(range_residual(b, fit.center, fit.radius, min_incidence_cos));
  return sum / static_cast<double>(beams.size());
}

}  // namespace refloc
