#include "motor_bridge.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

MotorBridge::MotorBridge(const RobotConfig& robot, const MotorBridgeConfig& config)
    : robot_(robot), config_(config), kinematics_(robot) {}

CommandVerdict MotorBridge::on_command(const BodyTwist& twist, int64_t receive_mono_us) {
  if (!std::isfinite(twist.vx) || !std::isfinite(twist.vy) || !std::isfinite(twist.wz)) {
    return CommandVerdict::kNonFinite;
  }
  // The same bound robot_sim applies: beyond it the number is a broken publisher, and
  // huge values would overflow the kinematics.
  const double max_speed_m_s = 10.0 * robot_.max_wheel_speed * robot_.wheel_radius;
  const double max_yaw_rate_rad_s = max_speed_m_s / (robot_.half_wheelbase_lx + robot_.half_track_ly);
  if (std::abs(twist.vx) > max_speed_m_s || std::abs(twist.vy) > max_speed_m_s ||
      std::abs(twist.wz) > max_yaw_rate_rad_s) {
    return CommandVerdict::kOutOfBounds;
  }
  command_ = twist;
  command_mono_us_ = receive_mono_us;
  has_command_ = true;
  return CommandVerdict::kAccepted;
}

WheelSetpoint MotorBridge::setpoint(int64_t now_mono_us) {
  const bool fresh =
      has_command_ && static_cast<double>(now_mono_us - command_mono_us_) <= config_.command_timeout_s * 1e6;
  if (was_commanded_ && !fresh) ++command_timeouts_;
  was_commanded_ = fresh;
  WheelSetpoint out;
  if (!fresh) return out;
  out.commanded = true;
  out.speed_rad_s = kinematics_.inverse(command_);
  double largest = 0.0;
  for (double w : out.speed_rad_s) largest = std::max(largest, std::abs(w));
  if (largest > robot_.max_wheel_speed) {
    for (double& w : out.speed_rad_s) w *= robot_.max_wheel_speed / largest;
  }
  return out;
}

std::optional<EncoderReading> MotorBridge::encoder_reading(const std::array<int32_t, 4>& ticks,
                                                           int64_t read_utime) {
  // Made-up stamps (the last one plus 1 us) would turn a clock step into absurd wheel
  // speeds downstream; skipping the sample loses one interval, which the odometry
  // integrates from the next one.
  if (read_utime <= last_encoder_utime_) {
    ++stamps_not_increasing_;
    return std::nullopt;
  }
  last_encoder_utime_ = read_utime;
  return EncoderReading{read_utime, ticks};
}

const char* to_string(CommandVerdict verdict) {
  switch (verdict) {
    case CommandVerdict::kAccepted:
      return "accepted";
    case CommandVerdict::kNonFinite:
      return "nonfinite";
    case CommandVerdict::kOutOfBounds:
      return "out_of_bounds";
  }
  return "unknown";
}

}  // namespace refloc
