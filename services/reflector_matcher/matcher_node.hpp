#pragma once
// The reflector_matcher service without LCM: fused poses and scans' detections in, in
// time order; per scan the prior chosen (PriorSelector), the match, the counters to bump
// and the heartbeat state. main.cpp and refloc-eval both run this. Every message is judged
// first (check_fused_pose / check_reflector_detections, then its stamp and, for REFLECTORS,
// the scan counter: common/input_stream_checks.hpp); a rejected one changes nothing.

#include "common/input_stream_checks.hpp"
#include "common/node_event.hpp"
#include "reflector_matcher/map_health_monitor.hpp"
#include "reflector_matcher/matcher_config_file.hpp"
#include "reflector_matcher/prior_selector.hpp"
#include "reflector_matcher/reflector_matcher.hpp"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace refloc {

struct MatcherOutput {
  /// false: the detections were rejected (events say why); nothing to publish, and result
  /// is still the last accepted scan's.
  bool accepted = false;
  std::vector<NodeEvent> events;  ///< rejection, clock re-anchor, counter reset, gap, INITIAL_POSE outcome
  int64_t missing_scans = -1;     ///< scan counters missing before this scan; -1: not known (offline)
  /// Detections come but none was usable for over a second: DEGRADED with starved_detail.
  bool starved = false;
  std::string starved_detail;
  int64_t utime = 0;  ///< the scan's [us]
  MatchResult result;
  PriorSource prior_source = PriorSource::kNone;
  bool tracking_association_failed = false;  ///< ReflectorMatcher::tracking_association_failed()
  StartupEvent startup_event = StartupEvent::kNone;

  /// Calls bump(name, increment) for each heartbeat counter this scan touches.
  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    if (!accepted) return;  // a rejected scan's counters are in events
    if (missing_scans >= 0) bump("gap_detections_messages", missing_scans);
    const bool had_prior = prior_source == PriorSource::kFusedPose || prior_source == PriorSource::kOwnPose;
    if (prior_source == PriorSource::kStartupWindow) bump("startup_scans_without_prior", 1);
    if (had_prior && (result.mode == MatchMode::kGlobal || tracking_association_failed))
      bump("tracking_failures", 1);
    if (result.mode == MatchMode::kGlobal) bump("global_relocalizations", 1);
    if (result.status == MatchStatus::kLost) bump("lost_scans", 1);
    if (result.status == MatchStatus::kAmbiguous) bump("ambiguous_scans", 1);
  }
  /// The heartbeat state after this message: OK, else DEGRADED with this detail. A rejected
  /// message keeps the last accepted scan's state until the input starves.
  bool ok() const { return !starved && result.status == MatchStatus::kOk; }
  const char* degraded_detail() const {
    if (starved) return starved_detail.c_str();
    return result.status == MatchStatus::kLost ? "last scan LOST" : "last scan AMBIGUOUS";
  }
};

class MatcherNode {
 public:
  /// robot_T_laser: the laser mount, for the fused POSE prior.
  MatcherNode(ReflectorMap map, const MatcherServiceConfig& config, const Pose2& robot_T_laser);

  /// One POSE at host wall-clock time host_utime [us]; the events of a rejected one.
  /// Valid until the next call.
  const std::vector<NodeEvent>& on_pose(const FusedPose& pose, int64_t host_utime);
  /// A user's INITIAL_POSE (checked like a POSE, but not against the POSE stream's stamps: it is
  /// the user's "now"); the events say it was taken, or why not.
  const std::vector<NodeEvent>& on_initial_pose(const FusedPose& pose);
  /// One scan's detections with its scan counter, at host_utime [us]; the reference stays
  /// valid until the next call.
  const MatcherOutput& on_detections(int64_t utime, int64_t scan_counter,
                                     const std::vector<ReflectorDetection>& detections, int64_t host_utime);

  /// Offline (logs, simulations): each message's own stamp is the host clock (stamps are
  /// judged only against the stream's history) and scan counters are not followed.
  const std::vector<NodeEvent>& on_pose(const FusedPose& pose) { return on_pose(pose, pose.utime); }
  const MatcherOutput& on_detections(int64_t utime, const std::vector<ReflectorDetection>& detections) {
    return on_detections(utime, kNoScanCounter, detections, utime);
  }
  static constexpr int64_t kNoScanCounter = -1;

  const ReflectorMatcher& matcher() const { return matcher_; }

  /// A laser scan: map health checks against it whether an expected reflector was in sight.
  void on_scan(const LaserScan& scan) {
    if (map_health_) map_health_->on_scan(scan);
  }
  /// The map evidence of every accepted OK scan; null when map_health is disabled.
  MapHealthMonitor* map_health() { return map_health_.get(); }

 private:
  ReflectorMatcher matcher_;
  std::unique_ptr<MapHealthMonitor> map_health_;
  PriorSelector selector_;
  InputStreamChecks detection_checks_;
  /// POSE stamps need not increase: fusion answers a laser fix with a pose at the fix's scan
  /// time, which can be older than its last pose from odometry.
  InputStreamChecks pose_checks_;
  std::vector<NodeEvent> pose_events_;
  MatcherOutput output_;
};

}  // namespace refloc
