#include "robot_sim/encoder_model.hpp"

#include <cmath>

namespace refloc {

EncoderModel::EncoderModel(int ticks_per_rev, int64_t start_ticks)
    : ticks_per_rad_(ticks_per_rev / (2.0 * M_PI)), start_ticks_(start_ticks) {}

std::array<int32_t, 4> EncoderModel::counts(const WheelArray& wheel_angles) const {
  std::array<int32_t, 4> out{};
  for (size_t i = 0; i < 4; ++i) {
    const auto count = start_ticks_ + static_cast<int64_t>(std::floor(wheel_angles[i] * ticks_per_rad_));
    // Keep the low 32 bits, as the controller's int32 register does.
    out[i] = static_cast<int32_t>(static_cast<uint32_t>(static_cast<uint64_t>(count)));
  }
  return out;
}

}  // namespace refloc
