#pragma once
// The reflector_matcher service without LCM: fused poses and scans' detections in, in
// time order; per scan the prior chosen (PriorSelector), the match, the counters to bump
// and the heartbeat state. main.cpp and refloc-eval both run this.

#include "reflector_matcher/matcher_config_file.hpp"
#include "reflector_matcher/prior_selector.hpp"
#include "reflector_matcher/reflector_matcher.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

struct MatcherOutput {
  int64_t utime = 0;  ///< the scan's [us]
  MatchResult result;
  PriorSource prior_source = PriorSource::kNone;
  StartupEvent startup_event = StartupEvent::kNone;

  /// Calls bump(name, increment) for each heartbeat counter this scan touches.
  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    const bool had_prior = prior_source == PriorSource::kFusedPose || prior_source == PriorSource::kOwnPose;
    if (prior_source == PriorSource::kStartupWindow) bump("startup_scans_without_prior", 1);
    if (had_prior && result.mode == MatchMode::kGlobal) bump("tracking_failures", 1);
    if (result.mode == MatchMode::kGlobal) bump("global_relocalizations", 1);
    if (result.status == MatchStatus::kLost) bump("lost_scans", 1);
    if (result.status == MatchStatus::kAmbiguous) bump("ambiguous_scans", 1);
  }
  /// The heartbeat state after this scan: OK, else DEGRADED with this detail.
  bool ok() const { return result.status == MatchStatus::kOk; }
  const char* degraded_detail() const {
    return result.status == MatchStatus::kLost ? "last scan LOST" : "last scan AMBIGUOUS";
  }
};

class MatcherNode {
 public:
  /// robot_T_laser: the laser mount, for the fused POSE prior.
  MatcherNode(ReflectorMap map, const MatcherServiceConfig& config, const Pose2& robot_T_laser);

  void on_pose(const FusedPose& pose) { selector_.on_pose(pose); }
  /// One scan's detections; the reference stays valid until the next call.
  const MatcherOutput& on_detections(int64_t utime, const std::vector<ReflectorDetection>& detections);

  const ReflectorMatcher& matcher() const { return matcher_; }

 private:
  ReflectorMatcher matcher_;
  PriorSelector selector_;
  MatcherOutput output_;
};

}  // namespace refloc
