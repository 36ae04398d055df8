#include "trajectory.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

void Trajectory::add(int64_t utime, const Pose2& pose) {
  if (samples_.empty() || utime >= samples_.back().utime) {
    samples_.push_back({utime, pose});
    return;
  }
  const auto it = std::upper_bound(samples_.begin(), samples_.end(), utime,
                                   [](int64_t t, const StampedPose& s) { return t < s.utime; });
  samples_.insert(it, {utime, pose});
}

std::optional<Pose2> Trajectory::at(int64_t utime, int64_t max_gap_us) const {
  if (samples_.empty() || utime < samples_.front().utime || utime > samples_.back().utime)
    return std::nullopt;
  const auto hi = std::lower_bound(samples_.begin(), samples_.end(), utime,
                                   [](const StampedPose& s, int64_t t) { return s.utime < t; });
  if (hi->utime == utime) return hi->pose;
  const auto lo = hi - 1;
  if (hi->utime - lo->utime > max_gap_us) return std::nullopt;
  const double f = static_cast<double>(utime - lo->utime) / static_cast<double>(hi->utime - lo->utime);
  return Pose2{lo->pose.x + f * (hi->pose.x - lo->pose.x), lo->pose.y + f * (hi->pose.y - lo->pose.y),
               wrap_angle(lo->pose.theta + f * angle_diff(hi->pose.theta, lo->pose.theta))};
}

ErrorStats compare(const Trajectory& estimate, const Trajectory& truth, int64_t from_utime) {
  ErrorStats stats;
  double sum_xy2 = 0.0, sum_th2 = 0.0;
  for (const auto& s : estimate.samples()) {
    if (s.utime < from_utime) continue;
    const auto t = truth.at(s.utime);
    if (!t) continue;
    const double exy2 = std::pow(s.pose.x - t->x, 2) + std::pow(s.pose.y - t->y, 2);
    const double eth = angle_diff(s.pose.theta, t->theta);
    sum_xy2 += exy2;
    sum_th2 += eth * eth;
    stats.max_xy_m = std::max(stats.max_xy_m, std::sqrt(exy2));
    // The truth's own motion over +-20 ms around the sample.
    const auto before = truth.at(s.utime - 20000), after = truth.at(s.utime + 20000);
    if (before && after &&
        (std::hypot(after->x - before->x, after->y - before->y) > kMovingSpeed_m_s * 0.04 ||
         std::abs(angle_diff(after->theta, before->theta)) > kMovingYawRate_rad_s * 0.04))
      stats.max_xy_moving_m = std::max(stats.max_xy_moving_m, std::sqrt(exy2));
    ++stats.count;
  }
  if (stats.count > 0) {
    stats.rmse_xy_m = std::sqrt(sum_xy2 / static_cast<double>(stats.count));
    stats.rmse_heading_rad = std::sqrt(sum_th2 / static_cast<double>(stats.count));
  }
  return stats;
}

}  // namespace refloc
