#pragma once
// A stand-in for the motor controller, so the example bridge runs without hardware:
// it takes wheel speed setpoints and turns simulated wheels at exactly those speeds,
// counting encoder ticks. On a robot this is the part to replace with the
// controller's own interface (CANopen, serial, EtherCAT, a vendor library): send
// four speed setpoints, read four cumulative counts. A real controller also ramps
// speeds under its own acceleration limit and has its own watchdog; keep both.

#include "common/mecanum_kinematics.hpp"

#include <array>
#include <cstdint>

namespace refloc {

class StubMotorController {
 public:
  /// ticks_per_rev: encoder counts per wheel revolution; start_ticks: the counts at
  /// power-up (a real controller's counts start anywhere and wrap as int32).
  StubMotorController(int ticks_per_rev, int32_t start_ticks, int64_t start_mono_us);

  /// New setpoints [rad/s], front-left, front-right, rear-right, rear-left.
  void set_wheel_speeds(const WheelArray& speed_rad_s, int64_t now_mono_us);
  /// The cumulative counts at now_mono_us (the wheels turned at the last setpoints).
  std::array<int32_t, 4> read_ticks(int64_t now_mono_us);

 private:
  void advance(int64_t now_mono_us);

  double ticks_per_rad_;
  WheelArray speed_rad_s_{};
  WheelArray angle_rad_{};  ///< since start
  int32_t start_ticks_;
  int64_t mono_us_;
};

}  // namespace refloc
