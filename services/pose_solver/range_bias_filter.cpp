#include "pose_solver/range_bias_filter.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

RangeBiasFilter::RangeBiasFilter(const RangeBiasConfig& config)
    : config_(config), mean_(config.prior_mean), sigma_(config.prior_sigma) {}

RangeBiasPrior RangeBiasFilter::prior_at(int64_t utime) {
  if (has_time_ && utime > last_utime_) {
    const double dt = 1e-6 * static_cast<double>(utime - last_utime_);
    const double variance = sigma_ * sigma_ + config_.drift * config_.drift * dt;
    sigma_ = std::min(std::sqrt(variance), config_.prior_sigma);
  }
  if (!has_time_ || utime > last_utime_) last_utime_ = utime;
  has_time_ = true;
  return RangeBiasPrior{mean_, sigma_, config_.estimate};
}

void RangeBiasFilter::update(double mean, double sigma) {
  if (!std::isfinite(mean) || !std::isfinite(sigma) || sigma < 0.0) return;
  mean_ = mean;
  sigma_ = std::min(sigma, config_.prior_sigma);
  ++updates_;
}

}  // namespace refloc
