#include "reflector_matcher/matcher_node.hpp"

#include "common/reflector_detection_check.hpp"
#include "reflector_matcher/fused_pose_check.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

namespace refloc {
namespace {

StampGuardLimits pose_stamp_limits() {
  StampGuardLimits limits = chain_stream_stamp_limits();
  limits.require_increasing = false;
  return limits;
}

}  // namespace

MatcherNode::MatcherNode(ReflectorMap map, const MatcherServiceConfig& config, const Pose2& robot_T_laser)
    : matcher_(std::move(map), config.matcher),
      selector_(config.prior, robot_T_laser),
      detection_checks_("detections", chain_stream_stamp_limits()),
      pose_checks_("pose", pose_stamp_limits()) {
  if (config.map_health.enabled)
    map_health_ =
        std::make_unique<MapHealthMonitor>(matcher_.map(), config.matcher.sensor, config.map_health);
}

const std::vector<NodeEvent>& MatcherNode::on_pose(const FusedPose& pose, int64_t host_utime) {
  pose_events_.clear();
  if (const InputFault fault = check_fused_pose(pose)) {
    pose_events_.push_back(pose_checks_.rejected(fault.reason, fault.detail, host_utime));
  } else if (pose_checks_.stamp_accepted(pose.utime, host_utime, pose_events_)) {
    pose_checks_.accepted(host_utime);
    selector_.on_pose(pose);
  }
  return pose_events_;
}

const std::vector<NodeEvent>& MatcherNode::on_initial_pose(const FusedPose& pose) {
  pose_events_.clear();
  FusedPose user = pose;
  user.ok = true;  // a user's pose carries no fusion status; check_fused_pose checks an OK one fully
  if (const InputFault fault = check_fused_pose(user)) {
    pose_events_.push_back({"initial_poses_rejected", NodeEvent::Level::kWarn,
                            fmt::format("INITIAL_POSE refused ({}): {}", fault.reason, fault.detail)});
    return pose_events_;
  }
  selector_.on_initial_pose(user);
  pose_events_.push_back(
      {"initial_poses_received", NodeEvent::Level::kInfo,
       fmt::format("INITIAL_POSE ({:.3f}, {:.3f}) m, {:.1f} deg: the prior for the next scans, "
                   "confirmed only if they match from it",
                   user.map_T_robot.x, user.map_T_robot.y, user.map_T_robot.theta * 180.0 / M_PI)});
  return pose_events_;
}

const MatcherOutput& MatcherNode::on_detections(int64_t utime, int64_t scan_counter,
                                                const std::vector<ReflectorDetection>& detections,
                                                int64_t host_utime) {
  output_.events.clear();
  output_.accepted = false;
  output_.missing_scans = -1;
  output_.starved = false;
  if (const InputFault fault = check_reflector_detections(detections)) {
    output_.events.push_back(detection_checks_.rejected(fault.reason, fault.detail, host_utime));
  } else if (detection_checks_.stamp_accepted(utime, host_utime, output_.events)) {
    detection_checks_.accepted(host_utime);
    output_.accepted = true;
  }
  if (!output_.accepted) {
    output_.starved = detection_checks_.starved(host_utime);
    if (output_.starved) output_.starved_detail = detection_checks_.starved_detail(host_utime);
    return output_;
  }
  if (scan_counter != kNoScanCounter)
    output_.missing_scans = detection_checks_.missing_before(scan_counter, utime, output_.events);
  output_.utime = utime;
  const PriorChoice choice = selector_.select(utime);
  output_.prior_source = choice.source;
  matcher_.match(detections, choice.prior ? &*choice.prior : nullptr, output_.result);
  output_.tracking_association_failed = matcher_.tracking_association_failed();
  if (matcher_.prior_settled_ambiguity())
    output_.events.push_back(
        {"ambiguities_settled_by_prior", NodeEvent::Level::kInfo,
         fmt::format("tracking from the prior failed and the map-wide search was AMBIGUOUS; the prior "
                     "admits one of its poses alone, ({:.2f}, {:.2f}) m: OK",
                     output_.result.map_T_laser.x, output_.result.map_T_laser.y)});
  if (matcher_.held_bare_overrule())
    output_.events.push_back(
        {"bare_overrules_held", NodeEvent::Level::kInfo,
         fmt::format("tracking from the prior failed and the map fits ({:.2f}, {:.2f}) m on only {} pairs: "
                     "AMBIGUOUS until another scan finds the same pose",
                     output_.result.map_T_laser.x, output_.result.map_T_laser.y,
                     matcher_.config().min_matches)});
  output_.startup_event = selector_.on_result(utime, output_.result);
  switch (selector_.take_initial_pose_event()) {
    case InitialPoseEvent::kConfirmed:
      output_.events.push_back({"initial_poses_confirmed", NodeEvent::Level::kInfo,
                                "INITIAL_POSE confirmed: a scan matched from it; tracking on from there"});
      break;
    case InitialPoseEvent::kExpired:
      output_.events.push_back({"initial_poses_expired", NodeEvent::Level::kWarn,
                                "INITIAL_POSE expired: no scan matched from it (another place, or too few "
                                "reflectors in view); relocalizing as before"});
      break;
    case InitialPoseEvent::kNone:
      break;
  }
  if (map_health_)
    map_health_->on_match(utime, detections, output_.result, choice.source == PriorSource::kFusedPose);
  return output_;
}

}  // namespace refloc
