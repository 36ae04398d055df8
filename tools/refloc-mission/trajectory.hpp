#pragma once
// Time-stamped pose sequences and their comparison against ground truth.

#include "common/se2.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace refloc {

struct StampedPose {
  int64_t utime = 0;  ///< [us]
  Pose2 pose;
};

/// Poses in time order (appends out of order are inserted in place).
class Trajectory {
 public:
  void add(int64_t utime, const Pose2& pose);
  /// Linear interpolation (heading on the circle); nullopt outside the covered time
  /// or across a gap longer than max_gap_us.
  std::optional<Pose2> at(int64_t utime, int64_t max_gap_us = 100000) const;
  const std::vector<StampedPose>& samples() const { return samples_; }
  bool empty() const { return samples_.empty(); }

 private:
  std::vector<StampedPose> samples_;
};

struct ErrorStats {
  size_t count = 0;
  double rmse_xy_m = 0.0;  ///< sqrt(mean(dx^2 + dy^2)) [m]
  double max_xy_m = 0.0;   ///< [m]
  /// Over the samples where the truth moves (faster than kMovingSpeed or kMovingYawRate): the
  /// "max while driving", without the robot standing at the start while the filter settles [m].
  double max_xy_moving_m = 0.0;
  double rmse_heading_rad = 0.0;
};

inline constexpr double kMovingSpeed_m_s = 0.02;
inline constexpr double kMovingYawRate_rad_s = 0.02;

/// Errors of estimate against truth interpolated at each estimate's time.
/// Estimates before from_utime are ignored.
ErrorStats compare(const Trajectory& estimate, const Trajectory& truth, int64_t from_utime = 0);

}  // namespace refloc
