#pragma once
// The matcher's LCM edge: the message <-> library conversions main.cpp makes. Header
// only and outside the LCM-free library, so a test that runs the chain across LCM
// (tests/pipeline) converts exactly as the service does.

#include "common/lcm_conversions.hpp"
#include "reflector_matcher/matcher_node.hpp"

#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <vector>

namespace refloc {

/// A POSE message as the prior selector reads it.
inline FusedPose fused_pose_from_message(const pose2d_t& msg) {
  return {msg.utime,
          {msg.x, msg.y, msg.theta},
          covariance_from_lcm(msg.covariance),
          msg.status == pose2d_t::STATUS_OK};
}

/// The detections of one REFLECTORS message, in message order.
inline void detections_from_message(const reflector_detections_t& msg, std::vector<ReflectorDetection>& out) {
  out.clear();
  for (const reflector_t& r : msg.reflectors) out.push_back(from_lcm(r));
}

/// REFLECTOR_MATCHES for the scan of `in`: each match carries its detection as received.
inline void to_message(const reflector_detections_t& in, const MatchResult& r, reflector_matches_t& out) {
  out.utime = in.utime;
  out.scan_counter = in.scan_counter;
  out.status = static_cast<int8_t>(r.status);  // MatchStatus and MatchMode have the message's values
  out.mode = static_cast<int8_t>(r.mode);
  out.hypothesis_score = r.hypothesis_score;
  out.runner_up_score = r.runner_up_score;
  out.hypothesis_x = r.map_T_laser.x;
  out.hypothesis_y = r.map_T_laser.y;
  out.hypothesis_theta = r.map_T_laser.theta;
  out.ndetections = static_cast<int32_t>(in.reflectors.size());
  out.matches.clear();
  for (const ReflectorMatch& m : r.matches) {
    out.matches.push_back({in.reflectors[static_cast<size_t>(m.detection_index)], m.map_id,
                           m.map_p_center.x(), m.map_p_center.y(), m.map_radius});
  }
  out.nmatches = static_cast<int32_t>(out.matches.size());  // encode trusts the length field
}

}  // namespace refloc
