#include "common/latency_window.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

LatencyWindow::LatencyWindow(size_t capacity) : samples_(capacity > 0 ? capacity : 1) {
  scratch_.reserve(samples_.size());
}

void LatencyWindow::add(double duration_us) {
  samples_[next_] = duration_us;
  next_ = (next_ + 1) % samples_.size();
  filled_ = std::min(filled_ + 1, samples_.size());
}

double LatencyWindow::percentile(double p) const {
  if (filled_ == 0) return 0.0;
  scratch_.assign(samples_.begin(), samples_.begin() + static_cast<long>(filled_));
  const double clamped = std::clamp(p, 0.0, 1.0);
  const size_t k = static_cast<size_t>(std::lround(clamped * static_cast<double>(filled_ - 1)));
  std::nth_element(scratch_.begin(), scratch_.begin() + static_cast<long>(k), scratch_.end());
  return scratch_[k];
}

void LatencyWindow::clear() {
  next_ = 0;
  filled_ = 0;
}

}  // namespace refloc
