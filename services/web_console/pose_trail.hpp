#pragma once
// A bounded trail of positions: a point is added once the pose moved step_m from the last one;
// beyond capacity the oldest goes (a ring buffer, no allocation after the first lap).

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace refloc {

class PoseTrail {
 public:
  PoseTrail(size_t capacity, double step_m) : capacity_(capacity), step_m_(step_m) {}

  /// Offer a position [m]; returns whether it was added.
  bool add(double x, double y) {
    if (size() > 0) {
      const std::array<double, 2>& last = points_[(next_ + points_.size() - 1) % points_.size()];
      if (std::hypot(x - last[0], y - last[1]) < step_m_) return false;
    }
    if (points_.size() < capacity_) {
      points_.push_back({x, y});
      next_ = points_.size() % capacity_;
    } else {
      points_[next_] = {x, y};
      next_ = (next_ + 1) % capacity_;
    }
    return true;
  }
  size_t size() const { return points_.size(); }
  /// The points oldest first.
  template <typename Visit>
  void for_each(Visit&& visit) const {
    const size_t start = points_.size() < capacity_ ? 0 : next_;
    for (size_t i = 0; i < points_.size(); ++i) visit(points_[(start + i) % points_.size()]);
  }

 private:
  size_t capacity_;
  double step_m_;
  std::vector<std::array<double, 2>> points_;
  size_t next_ = 0;  ///< where the next point goes once full
};

}  // namespace refloc
