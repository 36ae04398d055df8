#pragma once
// Wheel odometry of the Mecanum base: cumulative encoder counts in, odom-frame
// pose, body twist, growing covariance and a slip indicator out.

#include "common/mecanum_kinematics.hpp"
#include "common/odometry_noise.hpp"
#include "common/robot_config.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <array>
#include <cstdint>

namespace refloc {

/// The service's own integration rules (mecanum_odometry.json); geometry and the
/// increment noise are the robot's (RobotConfig, robot.json).
struct OdometryConfig {
  /// A gap between encoder samples longer than this restarts integration from
  /// the new counts (the motor controller was restarted; counts may have reset) [s].
  double max_gap = 1.0;
  /// Wheel speeds above this are taken as a counter glitch and skipped [rad/s].
  double max_plausible_wheel_speed = 100.0;
};

/// The odometry estimate after an encoder sample.
struct OdometryEstimate {
  int64_t utime = 0;   ///< time of the encoder sample [us]
  Pose2 odom_T_robot;  ///< pose in the odometry frame [m, m, rad]
  BodyTwist twist;     ///< body twist over the last interval [m/s, m/s, rad/s]
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< of odom_T_robot
  double distance = 0.0;                                 ///< path length since start [m]
  double slip_indicator = 0.0;  ///< |redundancy residual| over the last interval [m/s]
  Pose2 last_increment;         ///< body displacement over the last interval
};

enum class EncoderSampleResult { kIntegrated, kFirstSample, kOutOfOrder, kGapRestart, kImplausible };

class MecanumOdometry {
 public:
  MecanumOdometry(const RobotConfig& robot, const OdometryConfig& config);

  /// Integrate one sample of the four cumulative counts (int32, wrapping).
  EncoderSampleResult add_sample(int64_t utime, const std::array<int32_t, 4>& ticks);
  /// Take this sample as the new reference without integrating (the encoder clock
  /// stepped): pose, covariance and distance kept, twist zero.
  void restart_from(int64_t utime, const std::array<int32_t, 4>& ticks);

  const OdometryEstimate& estimate() const { return estimate_; }
  const MecanumKinematics& kinematics() const { return kinematics_; }

 private:
  MecanumKinematics kinematics_;
  OdometryNoise noise_;
  OdometryConfig config_;
  double rad_per_tick_;
  bool has_previous_ = false;
  int64_t previous_utime_ = 0;
  std::array<int32_t, 4> previous_ticks_{};
  OdometryEstimate estimate_;
};

}  // namespace refloc
