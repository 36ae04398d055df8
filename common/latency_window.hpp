#pragma once
// Percentiles of recent handler durations, for the heartbeat.

#include <cstddef>
#include <vector>

namespace refloc {

class LatencyWindow {
 public:
  explicit LatencyWindow(size_t capacity = 4096);
  void add(double duration_us);
  /// p in [0, 1]; 0 when empty. Does not clear the window.
  double percentile(double p) const;
  size_t size() const { return filled_; }
  void clear();

 private:
  std::vector<double> samples_;
  size_t next_ = 0;
  size_t filled_ = 0;
  mutable std::vector<double> scratch_;
};

}  // namespace refloc
