#include "stub_motor_controller.hpp"

#include <cmath>

namespace refloc {

StubMotorController::StubMotorController(int ticks_per_rev, int32_t start_ticks, int64_t start_mono_us)
    : ticks_per_rad_(ticks_per_rev / (2.0 * M_PI)), start_ticks_(start_ticks), mono_us_(start_mono_us) {}

void StubMotorController::set_wheel_speeds(const WheelArray& speed_rad_s, int64_t now_mono_us) {
  advance(now_mono_us);
  speed_rad_s_ = speed_rad_s;
}

std::array<int32_t, 4> StubMotorController::read_ticks(int64_t now_mono_us) {
  advance(now_mono_us);
  std::array<int32_t, 4> ticks{};
  for (size_t i = 0; i < 4; ++i) {
    // Counts wrap as int32, as a real controller's do: modular arithmetic in uint32.
    const auto counted = static_cast<int64_t>(std::floor(angle_rad_[i] * ticks_per_rad_));
    ticks[i] = static_cast<int32_t>(static_cast<uint32_t>(start_ticks_) + static_cast<uint32_t>(counted));
  }
  return ticks;
}

void StubMotorController::advance(int64_t now_mono_us) {
  if (now_mono_us <= mono_us_) return;
  const double dt = 1e-6 * static_cast<double>(now_mono_us - mono_us_);
  for (size_t i = 0; i < 4; ++i) angle_rad_[i] += speed_rad_s_[i] * dt;
  mono_us_ = now_mono_us;
}

}  // namespace refloc
