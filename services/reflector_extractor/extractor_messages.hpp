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
#include <refloc/reflector_clusters_t.hpp>
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

namespace refloc {

/// REFLECTOR_CLUSTERS for one scan (ClusterOutcome in the order of reflector_cluster_t's constants).
inline void to_message(const ExtractorOutput& o, reflector_clusters_t& out) {
  static_assert(static_cast<int>(ClusterOutcome::kFitFailed) == reflector_cluster_t::FIT_FAILED &&
                    static_cast<int>(ClusterOutcome::kOccluded) == reflector_cluster_t::OCCLUDED &&
                    static_cast<int>(ClusterOutcome::kAccepted) == reflector_cluster_t::ACCEPTED,
                "ClusterOutcome and reflector_cluster_t's outcome constants must agree");
  out.utime = o.utime;
  out.scan_counter = static_cast<int32_t>(o.scan_counter);
  out.energy_threshold_8bit = static_cast<float>(o.energy_threshold_8bit);
  out.energy_threshold_raw = static_cast<float>(o.energy_threshold_raw);
  out.rssi_read_as_8bit = o.rssi_read_as_8bit;
  out.clusters.resize(o.clusters.size());
  for (size_t i = 0; i < o.clusters.size(); ++i) {
    const ClusterRecord& c = o.clusters[i];
    reflector_cluster_t& m = out.clusters[i];
    m.first_beam = c.first_beam;
    m.last_beam = c.last_beam;
    m.nbeams = c.num_beams;
    m.outcome = static_cast<int8_t>(c.outcome);
    m.range = static_cast<float>(c.range);
    m.bearing = static_cast<float>(c.bearing);
    m.max_rssi_8bit = static_cast<float>(c.max_rssi_8bit);
  }
  out.nclusters = static_cast<int32_t>(out.clusters.size());  // LCM trusts the length field
}

}  // namespace refloc
