#include "lms100_driver/sensor_clock_filter.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

SensorClockFilter::SensorClockFilter(const SensorClockFilterConfig& config) : config_(config) {
  config_.window_bins = std::clamp<size_t>(config_.window_bins, 2, kMaxBins);
  config_.min_bins_for_drift = std::clamp<size_t>(config_.min_bins_for_drift, 2, config_.window_bins);
}

void SensorClockFilter::reset() {
  initialized_ = false;
  bin_head_ = 0;
  closed_bins_ = 0;
  bin_open_ = false;
  fitted_ = false;
  has_estimate_ = false;
  intercept_us_ = 0;
  drift_ = 0;
  late_in_a_row_ = 0;
}

void SensorClockFilter::restart_after_step() {
  ++resets_;
  reset();
}

int64_t SensorClockFilter::to_host_utime(int64_t sensor_us) const {
  const double x = static_cast<double>(sensor_us - origin_sensor_us_);
  return origin_host_us_ + static_cast<int64_t>(std::llround(x + intercept_us_ + drift_ * x));
}

SensorTimeMapping SensorClockFilter::update(uint32_t start_us, uint32_t transmit_us,
                                            int64_t host_receive_utime) {
  if (initialized_) {
    // Signed difference: forward across the 2^32 us wrap is positive; a sensor reboot is negative.
    const int64_t step = static_cast<int32_t>(transmit_us - last_transmit_raw_);
    if (step < 0) {
      restart_after_step();
    } else {
      transmit_unwrapped_ += step;
    }
  }
  if (!initialized_) {
    initialized_ = true;
    transmit_unwrapped_ = transmit_us;
    origin_sensor_us_ = transmit_us;
    origin_host_us_ = host_receive_utime;
  }
  last_transmit_raw_ = transmit_us;

  SensorTimeMapping mapping;
  mapping.sensor_transmit_us = transmit_unwrapped_;
  mapping.sensor_start_us = transmit_unwrapped_ - static_cast<int32_t>(transmit_us - start_us);

  double x = static_cast<double>(transmit_unwrapped_ - origin_sensor_us_);
  double y = static_cast<double>(host_receive_utime - origin_host_us_) - x;
  if (has_estimate_) {
    const double residual = y - (intercept_us_ + drift_ * x);
    const bool stepped_back = residual < -config_.step_backward_s * 1e6;
    late_in_a_row_ = residual > config_.step_forward_s * 1e6 ? late_in_a_row_ + 1 : 0;
    if (stepped_back || late_in_a_row_ >= config_.step_forward_count) {
      // The host clock was stepped (NTP, manual): the old envelope means nothing now.
      restart_after_step();
      initialized_ = true;
      transmit_unwrapped_ = transmit_us;
      origin_sensor_us_ = transmit_us;
      origin_host_us_ = host_receive_utime;
      mapping.sensor_transmit_us = transmit_unwrapped_;
      mapping.sensor_start_us = transmit_unwrapped_ - static_cast<int32_t>(transmit_us - start_us);
      x = 0;
      y = 0;
    }
  }

  if (!bin_open_) {
    bin_open_ = true;
    open_bin_ = {x, y};
    open_bin_start_us_ = x;
  } else if (x - open_bin_start_us_ >= config_.bin_s * 1e6) {
    close_bin();
    open_bin_ = {x, y};
    open_bin_start_us_ = x;
  } else if (y < open_bin_.offset_us) {
    open_bin_ = {x, y};
  }
  if (!fitted_) {
    // Until the drift is known, the envelope is the smallest offset seen.
    intercept_us_ = has_estimate_ ? std::min(intercept_us_, y) : y;
    has_estimate_ = true;
  }

  mapping.host_start_utime = std::min(to_host_utime(mapping.sensor_start_us), host_receive_utime);
  return mapping;
}

void SensorClockFilter::close_bin() {
  bins_[bin_head_] = open_bin_;
  bin_head_ = (bin_head_ + 1) % config_.window_bins;
  closed_bins_ = std::min(closed_bins_ + 1, config_.window_bins);
  if (closed_bins_ >= config_.min_bins_for_drift) fit();
}

void SensorClockFilter::fit() {
  const size_t n = closed_bins_;
  double mean_x = 0;
  double mean_y = 0;
  for (size_t i = 0; i < n; ++i) {
    mean_x += bins_[i].sensor_us;
    mean_y += bins_[i].offset_us;
  }
  mean_x /= static_cast<double>(n);
  mean_y /= static_cast<double>(n);
  double sxx = 0;
  double sxy = 0;
  for (size_t i = 0; i < n; ++i) {
    const double dx = bins_[i].sensor_us - mean_x;
    sxx += dx * dx;
    sxy += dx * (bins_[i].offset_us - mean_y);
  }
  if (sxx <= 0) return;
  drift_ = sxy / sxx;
  intercept_us_ = mean_y - drift_ * mean_x;
  fitted_ = true;
}

}  // namespace refloc
