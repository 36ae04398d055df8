#pragma once
// What robot_sim does with each message and tick, without LCM: a CMD_VEL command is
// accepted when finite and timed by its receipt; every tick advances the plant in its
// fixed internal steps up to now, recording the laser's true pose at each step for the
// renderer; the encoder tick reports the counts and whether the command just timed out.
//
// A command is refused (counted rejected_cmd_vel_nonfinite / rejected_cmd_vel_out_of_bounds,
// previous command kept) when a component is not finite or beyond kAbsurdCommandFactor times
// what the robot can do at max_wheel_speed (robot.json): such a number is a broken
// publisher, and 1e308 m/s would overflow the kinematics into NaN. Within that bound the
// plant scales the four wheel speeds down to max_wheel_speed together, as a motor controller
// saturates. CMD_VEL's stamp is not read: a command's age is judged from its receipt.
//
// The renderer's thread asks for the laser's pose at each beam's time through
// map_T_laser_at(), which advances the plant itself when that time is beyond the last
// tick: the ticks run on the LCM thread, and on a loaded host they lag by tens of
// milliseconds, after which the renderer drew beams from a pose 60-150 ms old (seen in CI
// as LASER_POSE 0.05-0.12 m off the truth at the scan's stamp: the simulator silently
// wrong). One mutex orders the two threads' use of the plant.

#include "common/node_event.hpp"
#include "common/robot_config.hpp"
#include "common/se2.hpp"
#include "robot_sim/encoder_model.hpp"
#include "robot_sim/mecanum_plant.hpp"
#include "robot_sim/pose_history.hpp"
#include "robot_sim/sim_setup.hpp"

#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace refloc {

struct EncoderSample {
  int64_t utime = 0;  ///< plant time of the counts [us]
  std::array<int32_t, 4> ticks{};
  bool command_timed_out = false;  ///< the command went stale since the previous sample
};

struct TruePose {
  int64_t utime = 0;  ///< [us]
  Pose2 map_T_robot;
};

class RobotSimNode {
 public:
  /// Laser poses kept for the renderer (2 s at the default 1 kHz step).
  static constexpr size_t kLaserPoseHistory = 2000;

  RobotSimNode(const RobotConfig& robot, const PlantSetup& setup, int64_t start_utime);

  /// Commands beyond this many times the robot's reach are refused.
  static constexpr double kAbsurdCommandFactor = 10.0;

  /// A CMD_VEL twist [m/s, m/s, rad/s] received at receipt_utime [us]; false (ignored,
  /// counted in events()) when not finite or absurd. Age is judged from receipt, as a
  /// motor controller does.
  bool on_command(const BodyTwist& twist, int64_t receipt_utime);
  /// Counters and warnings of the last on_command call.
  const std::vector<NodeEvent>& events() const { return events_; }
  /// Simulates in whole internal steps up to now_utime [us].
  void advance(int64_t now_utime);
  /// advance() then the encoder counts.
  EncoderSample encoder_tick(int64_t now_utime);
  /// advance() then the true pose.
  TruePose ground_truth_tick(int64_t now_utime);

  /// The laser's true map pose at utime [us], for the renderer's thread: the plant is
  /// advanced in whole steps up to utime first when it is behind; the last part of a step
  /// (under 1 ms by default) is not simulated, so such a beam gets the newest step's pose.
  /// A time more than kMaxRenderLead_us ahead of the plant, or older than the kept
  /// history, is not simulated towards: the nearest kept pose is returned and counted in
  /// laser_poses_outside_history().
  Pose2 map_T_laser_at(int64_t utime);
  /// Beam poses asked for outside what the simulation could give (see map_T_laser_at).
  uint64_t laser_poses_outside_history() const { return laser_poses_outside_history_.load(); }
  static constexpr int64_t kMaxRenderLead_us = 1'000'000;

  /// The laser's true poses over time, as recorded so far.
  std::shared_ptr<const PoseHistory> laser_poses() const { return laser_poses_; }
  const MecanumPlant& plant() const { return plant_; }

 private:
  Pose2 robot_T_laser_;
  MecanumPlant plant_;
  EncoderModel encoders_;
  int64_t step_us_;
  std::shared_ptr<PoseHistory> laser_poses_;
  bool was_stale_ = true;
  double max_speed_m_s_;       ///< body speed at max_wheel_speed
  double max_yaw_rate_rad_s_;  ///< yaw rate at max_wheel_speed
  std::vector<NodeEvent> events_;
  std::mutex plant_mutex_;  ///< the LCM thread's ticks and the renderer's map_T_laser_at
  std::atomic<uint64_t> laser_poses_outside_history_{0};

  void advance_locked(int64_t now_utime);
};

}  // namespace refloc
