#pragma once
// The simulated robot base: body twist commands go through the Mecanum inverse
// kinematics into four wheel speeds limited in speed and acceleration; the
// wheels move the body, with optional slip, and the true pose is integrated
// along exact arcs in fixed internal steps (1 kHz by default).
//
// A command older than command_timeout stops every wheel, decelerating under
// the wheel acceleration limit (like a motor controller's ramp-down), so the
// robot coasts to a stop over at most max_wheel_speed / max_wheel_accel seconds.
// Speed and acceleration limits scale all four wheels together, so a limited
// command keeps its direction.

#include "common/mecanum_kinematics.hpp"
#include "common/robot_config.hpp"
#include "common/se2.hpp"

#include <array>
#include <cstdint>
#include <random>

namespace refloc {

struct SlipConfig {
  /// Per-wheel ratio of ground speed to wheel surface speed minus 1 (e.g. a worn
  /// or soft roller: -0.01 moves 1 % less than the encoder says).
  /// The motor controller holds wheel speed, so the encoders do not see this:
  /// odometry drifts without the slip indicator noticing.
  WheelArray scale_error{0.0, 0.0, 0.0, 0.0};
  /// Per-wheel excess spin of a wheel that lost traction (oil, a bump): it turns
  /// this much faster than commanded, and the extra turning moves nothing. The
  /// encoders see it: this is what the odometry's slip indicator detects.
  WheelArray spin_excess{0.0, 0.0, 0.0, 0.0};
  /// Lateral slip: random body-y velocity noise, standard deviation per m/s of
  /// the robot's speed, drawn every internal step [(m/s) / (m/s)].
  double lateral_noise_per_speed = 0.0;
  unsigned seed = 1;  ///< random seed, so a simulation is reproducible
};

struct PlantConfig {
  double step = 0.001;           ///< internal integration step [s]
  double command_timeout = 0.2;  ///< a command older than this stops the wheels [s]
  SlipConfig slip;
};

class MecanumPlant {
 public:
  MecanumPlant(const RobotConfig& robot, const PlantConfig& config, const Pose2& map_T_robot,
               int64_t start_utime);

  /// A new body twist command [m/s, m/s, rad/s] received at utime [us].
  void command(const BodyTwist& twist, int64_t utime);
  /// Simulate up to utime [us] in internal steps (never backwards).
  void advance_to(int64_t utime);

  int64_t utime() const { return utime_; }
  const Pose2& map_T_robot() const { return map_T_robot_; }
  /// Wheel speeds as the motors turn them [rad/s].
  const WheelArray& wheel_speeds() const { return wheel_speed_; }
  /// Cumulative wheel rotation since start [rad], what the encoders see (spin included).
  const WheelArray& wheel_angles() const { return wheel_angle_; }
  /// The body twist actually achieved over the last step (slip included).
  const BodyTwist& body_twist() const { return body_twist_; }
  /// True while the last command is older than the timeout (or none arrived).
  bool command_stale() const;

 private:
  void step(double dt);

  RobotConfig robot_;
  PlantConfig config_;
  MecanumKinematics kinematics_;
  Pose2 map_T_robot_;
  int64_t utime_;
  BodyTwist command_;
  int64_t command_utime_ = 0;
  bool has_command_ = false;
  WheelArray wheel_speed_{};
  WheelArray wheel_angle_{};
  BodyTwist body_twist_;
  std::mt19937 rng_;
  std::normal_distribution<double> unit_normal_{0.0, 1.0};
};

}  // namespace refloc
