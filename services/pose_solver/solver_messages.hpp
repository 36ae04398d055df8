#pragma once
// The solver's LCM edge: the message <-> library conversions main.cpp makes. Header
// only and outside the LCM-free library, so a test that runs the chain across LCM
// (tests/pipeline) converts exactly as the service does.

#include "common/lcm_conversions.hpp"
#include "pose_solver/solver_node.hpp"

#include <refloc/pose2d_t.hpp>

#include <vector>

namespace refloc {

inline MatchVerdict match_verdict_from_message(int8_t status) {
  if (status == reflector_matches_t::STATUS_OK) return MatchVerdict::kOk;
  return status == reflector_matches_t::STATUS_AMBIGUOUS ? MatchVerdict::kAmbiguous : MatchVerdict::kLost;
}

/// LASER_POSE from one fix.
inline void to_message(const LaserFix& fix, pose2d_t& out) {
  constexpr int8_t kStatus[] = {pose2d_t::STATUS_OK, pose2d_t::STATUS_DEGRADED, pose2d_t::STATUS_LOST,
                                pose2d_t::STATUS_AMBIGUOUS};  // in LaserFixStatus order
  out.utime = fix.utime;
  out.status = kStatus[static_cast<int>(fix.status)];
  out.x = fix.map_T_robot.x;
  out.y = fix.map_T_robot.y;
  out.theta = fix.map_T_robot.theta;
  covariance_to_lcm(fix.covariance, out.covariance);
  out.reflectors_used = fix.reflectors_used;
  out.residual = fix.residual;
}

}  // namespace refloc
