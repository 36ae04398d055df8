#include "robot_sim/robot_sim_node.hpp"

#include "common/input_sanity.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {

RobotSimNode::RobotSimNode(const RobotConfig& robot, const PlantSetup& setup, int64_t start_utime)
    : robot_T_laser_(robot.robot_T_laser),
      plant_(robot, setup.plant, setup.initial_map_T_robot, start_utime),
      encoders_(robot.encoder_ticks_per_rev, setup.encoder_start_ticks),
      step_us_(static_cast<int64_t>(std::llround(setup.plant.step * 1e6))),
      laser_poses_(std::make_shared<PoseHistory>(kLaserPoseHistory)),
      max_speed_m_s_(robot.max_wheel_speed * robot.wheel_radius),
      max_yaw_rate_rad_s_(robot.max_wheel_speed * robot.wheel_radius /
                          (robot.half_wheelbase_lx + robot.half_track_ly)) {
  laser_poses_->add(plant_.utime(), plant_.map_T_robot() * robot_T_laser_);
}

bool RobotSimNode::on_command(const BodyTwist& twist, int64_t receipt_utime) {
  events_.clear();
  if (!all_finite({twist.vx, twist.vy, twist.wz})) {
    events_.push_back(
        {"rejected_cmd_vel_nonfinite", NodeEvent::Level::kWarn,
         fmt::format("CMD_VEL ({}, {}, {}) refused: not finite", twist.vx, twist.vy, twist.wz)});
    return false;
  }
  const double speed_bound = kAbsurdCommandFactor * max_speed_m_s_;
  const double yaw_bound = kAbsurdCommandFactor * max_yaw_rate_rad_s_;
  if (!finite_abs_at_most(twist.vx, speed_bound) || !finite_abs_at_most(twist.vy, speed_bound) ||
      !finite_abs_at_most(twist.wz, yaw_bound)) {
    events_.push_back({"rejected_cmd_vel_out_of_bounds", NodeEvent::Level::kWarn,
                       fmt::format("CMD_VEL ({}, {}, {}) refused: beyond {:.1f} m/s or {:.1f} rad/s",
                                   twist.vx, twist.vy, twist.wz, speed_bound, yaw_bound)});
    return false;
  }
  const std::lock_guard<std::mutex> lock(plant_mutex_);
  plant_.command(twist, receipt_utime);
  return true;
}

void RobotSimNode::advance(int64_t now_utime) {
  const std::lock_guard<std::mutex> lock(plant_mutex_);
  advance_locked(now_utime);
}

Pose2 RobotSimNode::map_T_laser_at(int64_t utime) {
  {
    const std::lock_guard<std::mutex> lock(plant_mutex_);
    const int64_t plant_utime = plant_.utime();
    if (utime > plant_utime + kMaxRenderLead_us ||
        utime < plant_utime - static_cast<int64_t>(kLaserPoseHistory) * step_us_) {
      ++laser_poses_outside_history_;
    } else {
      advance_locked(utime);
    }
  }
  return laser_poses_->at(utime);
}

void RobotSimNode::advance_locked(int64_t now_utime) {
  while (plant_.utime() + step_us_ <= now_utime) {
    plant_.advance_to(plant_.utime() + step_us_);
    laser_poses_->add(plant_.utime(), plant_.map_T_robot() * robot_T_laser_);
  }
}

EncoderSample RobotSimNode::encoder_tick(int64_t now_utime) {
  const std::lock_guard<std::mutex> lock(plant_mutex_);
  advance_locked(now_utime);
  EncoderSample sample;
  sample.utime = plant_.utime();
  sample.ticks = encoders_.counts(plant_.wheel_angles());
  const bool stale = plant_.command_stale();
  sample.command_timed_out = stale && !was_stale_;
  was_stale_ = stale;
  return sample;
}

TruePose RobotSimNode::ground_truth_tick(int64_t now_utime) {
  const std::lock_guard<std::mutex> lock(plant_mutex_);
  advance_locked(now_utime);
  return {plant_.utime(), plant_.map_T_robot()};
}

}  // namespace refloc
