#pragma once
// The range offset b kept across scans: a 1-D Kalman filter on a random walk. Between scans its
// variance grows by drift^2 dt (capped at the configured prior's, which is what is known about b
// without any scan); a scan that estimates b (the joint solve with this prior) gives the
// posterior. A scan that cannot estimate it leaves the mean and only the grown variance.

#include "pose_solver/range_bias_refinement.hpp"
#include "pose_solver/solver_config.hpp"

#include <cstdint>

namespace refloc {

class RangeBiasFilter {
 public:
  explicit RangeBiasFilter(const RangeBiasConfig& config);

  /// The prior for a scan at utime [us]: the estimate grown by the drift since the last scan.
  /// A stamp older than the last one adds no time (a replay or a clock step).
  RangeBiasPrior prior_at(int64_t utime);
  /// Take the scan's posterior of b (mean, sigma [m]) as the new estimate.
  void update(double mean, double sigma);

  double mean() const { return mean_; }    ///< [m]
  double sigma() const { return sigma_; }  ///< [m]
  int64_t updates() const { return updates_; }

 private:
  RangeBiasConfig config_;
  double mean_;
  double sigma_;
  int64_t last_utime_ = 0;
  bool has_time_ = false;
  int64_t updates_ = 0;
};

}  // namespace refloc
