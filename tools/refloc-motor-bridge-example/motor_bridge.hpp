#pragma once
// The motor-controller side of refloc's contract, without LCM: CMD_VEL twists in,
// four wheel speed setpoints out (zero when no command is fresh), and the
// controller's cumulative encoder counts out as a WHEEL_ENCODERS reading.
//
// The command's age is judged from its receipt on this computer's monotonic clock,
// never from its stamp: a motor controller must stop when commands stop arriving,
// whatever clock the commander runs on. The navigator sends CMD_VEL at its control
// rate while a goal is active, zero for 0.5 s after it ends, and then nothing, so
// silence is a normal way for commands to end, not only a fault.

#include "common/body_twist.hpp"
#include "common/mecanum_kinematics.hpp"
#include "common/robot_config.hpp"

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace refloc {

struct MotorBridgeConfig {
  double command_timeout_s = 0.2;  ///< a command older than this stops the wheels [s]
  double encoder_rate_hz = 100.0;  ///< WHEEL_ENCODERS publish rate [Hz]
};

/// What the bridge tells the motor controller on one control tick.
struct WheelSetpoint {
  WheelArray speed_rad_s{};  ///< front-left, front-right, rear-right, rear-left [rad/s]
  bool commanded = false;    ///< false: no fresh command, the setpoint is zero
};

/// One WHEEL_ENCODERS sample: host wall-clock time the counts were read [us] and
/// the cumulative counts, wrapping as int32.
struct EncoderReading {
  int64_t utime = 0;
  std::array<int32_t, 4> ticks{};
};

enum class CommandVerdict { kAccepted, kNonFinite, kOutOfBounds };

class MotorBridge {
 public:
  MotorBridge(const RobotConfig& robot, const MotorBridgeConfig& config);

  /// A CMD_VEL twist [m/s, m/s, rad/s] received at receive_mono_us (monotonic clock).
  /// A non-finite twist, or one over 10 x what the robot reaches at max_wheel_speed
  /// (a broken publisher), is refused and the previous command kept; it still ages out.
  CommandVerdict on_command(const BodyTwist& twist, int64_t receive_mono_us);

  /// The wheel speeds to send now: the last command through the Mecanum inverse
  /// kinematics, all four scaled down together to max_wheel_speed (so the motion keeps
  /// its direction); zero when no command arrived within command_timeout_s.
  WheelSetpoint setpoint(int64_t now_mono_us);

  /// The counts read from the controller at host wall-clock time read_utime as a
  /// WHEEL_ENCODERS reading; nothing when the stamp is not after the previous one
  /// (mecanum_odometry would refuse it; counted in stamps_not_increasing).
  std::optional<EncoderReading> encoder_reading(const std::array<int32_t, 4>& ticks, int64_t read_utime);

  /// Times a fresh command turned stale (the wheels were stopped by the timeout).
  int64_t command_timeouts() const { return command_timeouts_; }
  int64_t stamps_not_increasing() const { return stamps_not_increasing_; }

 private:
  RobotConfig robot_;
  MotorBridgeConfig config_;
  MecanumKinematics kinematics_;
  BodyTwist command_;
  int64_t command_mono_us_ = 0;
  bool has_command_ = false;
  bool was_commanded_ = false;
  int64_t command_timeouts_ = 0;
  int64_t stamps_not_increasing_ = 0;
  int64_t last_encoder_utime_ = 0;
};

/// "accepted", "nonfinite", "out_of_bounds": for counters and logs.
const char* to_string(CommandVerdict verdict);

}  // namespace refloc
