#pragma once
// pose_fusion's LCM edge: the message <-> library conversions main.cpp makes. Header only and
// outside the LCM-free library (like pose_solver/solver_messages.hpp).

#include "common/lcm_conversions.hpp"
#include "pose_fusion/fusion_node.hpp"

#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_matches_t.hpp>

namespace refloc {

inline int8_t to_message_status(FusionStatus s) {
  switch (s) {
    case FusionStatus::kInitializing:
      return pose2d_t::STATUS_INITIALIZING;
    case FusionStatus::kOk:
      return pose2d_t::STATUS_OK;
    case FusionStatus::kDegraded:
      return pose2d_t::STATUS_DEGRADED;
    case FusionStatus::kLost:
      return pose2d_t::STATUS_LOST;
  }
  return pose2d_t::STATUS_LOST;
}

inline OdometrySample from_message(const odometry_t& msg) {
  return {msg.utime, {msg.vx, msg.vy, msg.wz}, {msg.x, msg.y, msg.theta}, msg.distance};
}

inline LaserFixInput from_message(const pose2d_t& msg) {
  LaserFixInput in;
  in.utime = msg.utime;
  in.map_T_robot = {msg.x, msg.y, msg.theta};
  in.covariance = covariance_from_lcm(msg.covariance);
  in.status = msg.status == pose2d_t::STATUS_OK         ? FixStatus::kOk
              : msg.status == pose2d_t::STATUS_DEGRADED ? FixStatus::kDegraded
                                                        : FixStatus::kNoPose;
  in.reflectors_used = msg.reflectors_used;
  return in;
}

inline pose2d_t to_message(const FusionOutput& pose) {
  pose2d_t out{};
  out.utime = pose.utime;
  out.x = pose.map_T_robot.x;
  out.y = pose.map_T_robot.y;
  out.theta = pose.map_T_robot.theta;
  covariance_to_lcm(pose.covariance, out.covariance);
  out.status = to_message_status(pose.status);
  out.reflectors_used = pose.reflectors_used;
  out.residual = 0.0;
  return out;
}

inline void from_message(const reflector_matches_t& msg, MatchesInput& in) {
  in.utime = msg.utime;
  in.scan_counter = msg.scan_counter;
  in.matcher_ok = msg.status == reflector_matches_t::STATUS_OK;
  matches_from_message(msg, in.detections, in.matches);
}

}  // namespace refloc
