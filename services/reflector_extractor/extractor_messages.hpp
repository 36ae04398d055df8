#pragma once
// The extractor's LCM edge: the message <-> library conversions main.cpp makes. Header
// only and outside the LCM-free library, so a test that runs the chain across LCM
// (tests/pipeline) converts exactly as the service does.

#include "common/lcm_conversions.hpp"
#include "common/odometry_sample.hpp"
#include "reflector_extractor/extractor_node.hpp"

#include <refloc/laser_scan_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_detections_t.hpp>

namespace refloc {

/// The part of ODOMETRY motion compensation reads: its time and body twist.
inline OdometrySample odometry_twist_from_message(const odometry_t& msg) {
  OdometrySample sample;
  sample.utime = msg.utime;
  sample.twist = {msg.vx, msg.vy, msg.wz};
  return sample;
}

/// LASER_POSE as motion compensation reads it (only status OK fixes are used).
inline LaserPoseFix laser_pose_from_message(const pose2d_t& msg) {
  return {msg.utime,
          {msg.x, msg.y, msg.theta},
          covariance_from_lcm(msg.covariance),
          msg.status == pose2d_t::STATUS_OK};
}

/// LMS100_SCAN as it came, judged by nobody here: every check is ExtractorNode's
/// (check_scan), so a broken header is counted by its reason like any other fault.
inline void scan_from_message(const laser_scan_t& msg, LaserScan& out) { copy_from_lcm(msg, out); }

/// REFLECTORS for one scan.
inline void to_message(const ExtractorOutput& o, reflector_detections_t& out) {
  out.utime = o.utime;
  out.scan_counter = static_cast<int32_t>(o.scan_counter);
  out.clusters_considered = o.stats.clusters_considered;
  out.clusters_rejected = o.stats.rejected();
  out.reflectors.clear();
  for (const ReflectorDetection& d : o.detections) out.reflectors.push_back(to_lcm(d));
  out.nreflectors = static_cast<int32_t>(out.reflectors.size());  // LCM trusts the length field
}

}  // namespace refloc
