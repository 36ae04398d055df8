#pragma once
// Incremental wheel encoders as a motor controller reports them: cumulative
// counts quantised to whole ticks, held in int32 and wrapping around.

#include "common/mecanum_kinematics.hpp"

#include <array>
#include <cstdint>

namespace refloc {

class EncoderModel {
 public:
  /// ticks_per_rev per wheel revolution; start_ticks is the count at zero angle
  /// (set it near INT32_MAX to exercise the wrap-around downstream).
  explicit EncoderModel(int ticks_per_rev, int64_t start_ticks = 0);

  /// Counts for cumulative wheel angles [rad] (front-left, front-right, rear-right, rear-left).
  std::array<int32_t, 4> counts(const WheelArray& wheel_angles) const;

 private:
  double ticks_per_rad_;
  int64_t start_ticks_;
};

}  // namespace refloc
