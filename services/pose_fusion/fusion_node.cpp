#include "pose_fusion/fusion_node.hpp"

#include <fmt/format.h>

namespace refloc {

FusionHealth fusion_health(FusionStatus status) {
  if (status == FusionStatus::kOk) return {true, ""};
  return {false, to_string(status)};
}

const char* fix_result_counter(FixResult result) {
  switch (result) {
    case FixResult::kAccepted:
      return "fixes_accepted";
    case FixResult::kInitialised:
      return "initialisations";
    case FixResult::kRejectedGate:
      return "fixes_rejected_gate";
    case FixResult::kTooOld:
      return "fixes_too_old";
    case FixResult::kWaitingForGood:
      return "fixes_not_good_enough_to_start";
    case FixResult::kDeferred:
      return "fixes_deferred";
  }
  return "fixes_unknown_result";
}

FusionNode::FusionNode(const FusionServiceConfig& config, const OdometryNoise& noise)
    : noise_(noise),
      fusion_(config.fusion),
      continuity_(config.continuity),
      silence_(config.odometry_timeout) {}

void FusionNode::event(const char* counter, NodeEvent::Level level, std::string log) {
  events_.push_back({counter, level, std::move(log)});
}

void FusionNode::count_fix_result(FixResult result) {
  if (result == FixResult::kRejectedGate) {
    event(fix_result_counter(result), NodeEvent::Level::kDebug,
          fmt::format("fix rejected, Mahalanobis^2 {:.1f}", fusion_.last_mahalanobis_squared()));
  } else {
    event(fix_result_counter(result));
  }
}

void FusionNode::apply_step(const OdometrySample& sample, const OdometryStep& step) {
  switch (step.kind) {
    case OdometryStepKind::kFirst:
      break;
    case OdometryStepKind::kBackwards:
      // A restarted odometry service on another clock: take the next step from here.
      event("odometry_restarts", NodeEvent::Level::kWarn,
            fmt::format("ODOMETRY went back in time by {:.3f} s: new odometry frame", -step.gap));
      break;
    case OdometryStepKind::kContinuous:
      fusion_.add_odometry(sample.utime, step.delta, increment_covariance(step.delta, noise_));
      break;
    case OdometryStepKind::kSeam:
      event(step.restarted ? "odometry_restarts" : "odometry_gaps", NodeEvent::Level::kWarn,
            fmt::format(
                "ODOMETRY {} after {:.3f} s: motion meanwhile unobserved, waiting for a fix to re-anchor",
                step.restarted ? "restarted" : "resumed", step.gap));
      fusion_.add_odometry_seam(sample.utime, step.delta,
                                increment_covariance(step.delta, noise_) + step.unobserved_q);
      break;
  }
}

const FusionOutput& FusionNode::on_odometry(const OdometrySample& sample, int64_t now_mono_us) {
  events_.clear();
  apply_step(sample, continuity_.next(sample));
  for (const FixResult r : fusion_.deferred_results()) count_fix_result(r);
  const FusionStatus status = fusion_.status(sample.utime);
  if (status != published_status_) {
    event(nullptr, NodeEvent::Level::kInfo,
          fmt::format("status {} -> {}", to_string(published_status_), to_string(status)));
    published_status_ = status;
  }
  const PoseEstimate& e = fusion_.estimate();
  pose_ = {sample.utime, e.map_T_robot, e.covariance, status, reflectors_used_};
  silence_.on_odometry(now_mono_us, pose_.utime);
  return pose_;
}

std::optional<FusionOutput> FusionNode::on_fix(const LaserFixInput& input, int64_t now_mono_us) {
  events_.clear();
  const std::optional<PoseFix> fix = usable_fix(input);
  if (!fix) {
    event("fixes_unusable");
    return std::nullopt;
  }
  std::optional<FusionOutput> out;
  if (silence_.publish_fix(now_mono_us, input.utime)) {
    // No ODOMETRY (its service restarting?): the fix itself, DEGRADED, rather than no POSE at all.
    out = FusionOutput{input.utime, input.map_T_robot, input.covariance, FusionStatus::kDegraded,
                       input.reflectors_used};
    event("fixes_published_without_odometry");
  }
  const FixResult result = fusion_.add_fix(*fix);
  count_fix_result(result);
  if (result == FixResult::kAccepted || result == FixResult::kInitialised)
    reflectors_used_ = input.reflectors_used;
  if (result == FixResult::kInitialised) {
    const Pose2& p = input.map_T_robot;
    event(nullptr, NodeEvent::Level::kInfo,
          fmt::format("initialised from the fix at utime {}: ({:.3f}, {:.3f}, {:.4f})", input.utime, p.x, p.y,
                      p.theta));
  }
  return out;
}

}  // namespace refloc
