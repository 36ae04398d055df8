#include "robot_sim/pose_history.hpp"

namespace refloc {

PoseHistory::PoseHistory(size_t capacity) : ring_(capacity > 0 ? capacity : 1) {}

const PoseHistory::Sample& PoseHistory::sample(size_t i) const {
  return ring_[(next_ + ring_.size() - count_ + i) % ring_.size()];
}

void PoseHistory::add(int64_t utime, const Pose2& pose) {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (count_ > 0 && utime <= sample(count_ - 1).utime) return;
  ring_[next_] = {utime, pose};
  next_ = (next_ + 1) % ring_.size();
  if (count_ < ring_.size()) ++count_;
}

Pose2 PoseHistory::at(int64_t utime) const {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (count_ == 0) return {};
  if (utime <= sample(0).utime) return sample(0).pose;
  if (utime >= sample(count_ - 1).utime) return sample(count_ - 1).pose;
  size_t lo = 0, hi = count_ - 1;  // sample(lo).utime < utime < sample(hi).utime
  while (hi - lo > 1) {
    const size_t mid = (lo + hi) / 2;
    (sample(mid).utime <= utime ? lo : hi) = mid;
  }
  const Sample& a = sample(lo);
  const Sample& b = sample(hi);
  const double f = static_cast<double>(utime - a.utime) / static_cast<double>(b.utime - a.utime);
  return {a.pose.x + f * (b.pose.x - a.pose.x), a.pose.y + f * (b.pose.y - a.pose.y),
          wrap_angle(a.pose.theta + f * angle_diff(b.pose.theta, a.pose.theta))};
}

}  // namespace refloc
