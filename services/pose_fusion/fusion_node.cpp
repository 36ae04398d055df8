// FusionNode: every message checked, counted and logged before the filter sees it;
// longer than 300 lines because the three input streams share one health and event list.
#include "pose_fusion/fusion_node.hpp"

#include "common/input_sanity.hpp"
#include "common/reflector_detection_check.hpp"
#include "pose_fusion/fusion_input_checks.hpp"

#include <fmt/format.h>

namespace refloc {
namespace {

const char* odometry_stamp_counter(StampVerdict v) {
  switch (v) {
    case StampVerdict::kAhead:
      return "rejected_odometry_stamp_ahead";
    case StampVerdict::kBehind:
      return "rejected_odometry_stamp_behind";
    case StampVerdict::kNotIncreasing:
      return "rejected_odometry_stamp_not_increasing";
    case StampVerdict::kReanchored:
      return "reanchored_odometry";
    case StampVerdict::kAccepted:
      break;
  }
  return nullptr;
}

const char* fix_stamp_counter(StampVerdict v) {
  switch (v) {
    case StampVerdict::kAhead:
      return "rejected_laser_pose_stamp_ahead";
    case StampVerdict::kBehind:
      return "rejected_laser_pose_stamp_behind";
    case StampVerdict::kNotIncreasing:
      return "rejected_laser_pose_stamp_not_increasing";
    case StampVerdict::kReanchored:
      return "reanchored_laser_pose";
    case StampVerdict::kAccepted:
      break;
  }
  return nullptr;
}

const char* odometry_value_counter(InputProblem p) {
  return p == InputProblem::kNonFinite ? "rejected_odometry_nonfinite" : "rejected_odometry_out_of_bounds";
}

const char* fix_value_counter(InputProblem p) {
  switch (p) {
    case InputProblem::kNonFinite:
      return "rejected_laser_pose_nonfinite";
    case InputProblem::kCovariance:
      return "rejected_laser_pose_covariance";
    default:
      return "rejected_laser_pose_out_of_bounds";
  }
}

/// Variances beyond this in the filter's own estimate mean it diverged [m^2, rad^2].
constexpr double kMaxEstimateVariance = 1e12;

bool output_sane(const FusionOutput& pose) {
  const Pose2& p = pose.map_T_robot;
  return all_finite({p.x, p.y, p.theta}) && is_usable_covariance(pose.covariance, kMaxEstimateVariance);
}

}  // namespace

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
    case FixResult::kAheadOfOdometry:
      return "rejected_laser_pose_ahead_of_odometry";
  }
  return "fixes_unknown_result";
}

namespace {

/// What the filter takes as random of the robot's odometry noise: all of it, or while it
/// estimates the calibration error only the configured share.
OdometryNoise random_odometry_noise(const FusionServiceConfig& config, OdometryNoise noise) {
  if (!config.fusion.model.estimate_odometry_error) return noise;
  const double f = config.odometry_random_noise_fraction;
  noise.translation_variance_per_m *= f;
  noise.heading_variance_per_m *= f;
  noise.heading_variance_per_rad *= f;
  noise.translation_variance_per_rad *= f;
  return noise;
}

}  // namespace

FusionNode::FusionNode(const FusionServiceConfig& config, const OdometryNoise& noise)
    : config_(config),
      noise_(random_odometry_noise(config, noise)),
      fusion_(config.fusion),
      continuity_(config.continuity),
      silence_(config.odometry_timeout) {}

void FusionNode::event(const char* counter, NodeEvent::Level level, std::string log) {
  events_.push_back({counter, level, std::move(log)});
}

void FusionNode::reject(const char* counter, std::string log) {
  last_rejection_ = counter;
  last_rejection_mono_us_ = now_mono_us_;
  event(counter, NodeEvent::Level::kWarn, std::move(log));
}

void FusionNode::published(FusionStatus status, int64_t now_mono_us) {
  output_status_ = status;
  last_output_mono_us_ = now_mono_us;
}

void FusionNode::count_fix_result(FixResult result) {
  if (result == FixResult::kRejectedGate) {
    event(fix_result_counter(result), NodeEvent::Level::kDebug,
          fmt::format("fix rejected, Mahalanobis^2 {:.1f}", fusion_.last_mahalanobis_squared()));
  } else if (result == FixResult::kAheadOfOdometry) {
    reject(fix_result_counter(result),
           fmt::format("LASER_POSE more than {:.1f} s ahead of the latest ODOMETRY: refused",
                       config_.fusion.history));
  } else {
    event(fix_result_counter(result));
  }
}

bool FusionNode::odometry_acceptable(const OdometrySample& sample, int64_t host_utime) {
  const InputProblem problem = check_odometry_values(sample);
  if (problem != InputProblem::kNone) {
    reject(odometry_value_counter(problem), fmt::format("ODOMETRY at utime {} refused: {} pose or distance",
                                                        sample.utime, to_string(problem)));
    return false;
  }
  const StampVerdict verdict = odometry_stamps_.check(sample.utime, host_utime);
  if (!stamp_accepted(verdict)) {
    reject(odometry_stamp_counter(verdict),
           fmt::format("ODOMETRY at utime {} refused: stamp {} ({} us from the stream's clock)", sample.utime,
                       to_string(verdict), -odometry_stamps_.last_deviation_us()));
    return false;
  }
  if (verdict == StampVerdict::kReanchored) {
    event(odometry_stamp_counter(verdict), NodeEvent::Level::kWarn,
          "ODOMETRY clock stepped: the stream's stamps are believed from here");
  }
  for (int64_t missing = odometry_gaps_.on_stamp(sample.utime); missing > 0; --missing)
    event("gap_odometry_messages");
  return true;
}

void FusionNode::apply_step(const OdometrySample& sample, const OdometryStep& step) {
  switch (step.kind) {
    case OdometryStepKind::kFirst:
    case OdometryStepKind::kImplausible:
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

const FusionOutput* FusionNode::on_odometry(const OdometrySample& sample, int64_t now_mono_us,
                                            int64_t host_utime) {
  events_.clear();
  now_mono_us_ = now_mono_us;
  if (!odometry_acceptable(sample, host_utime)) return nullptr;
  const OdometryStep step = continuity_.next(sample);
  if (step.kind == OdometryStepKind::kImplausible) {
    reject("rejected_odometry_jump",
           fmt::format("ODOMETRY at utime {} refused: moved further in {:.3f} s than the robot can",
                       sample.utime, step.gap));
    return nullptr;
  }
  apply_step(sample, step);
  for (const FixResult r : fusion_.deferred_results()) count_fix_result(r);
  const FusionStatus status = fusion_.status(sample.utime);
  const PoseEstimate& e = fusion_.estimate();
  pose_ = {sample.utime, e.map_T_robot, e.covariance, status, reflectors_used_};
  if (!output_sane(pose_)) {
    // Cannot happen from checked inputs; should it anyway, start over rather than publish it.
    fusion_ = PoseFusion(config_.fusion);
    reject("filter_resets_nonfinite",
           "the filter's estimate became non-finite: re-initialising from the next fix");
    return nullptr;
  }
  if (status != published_status_) {
    event(nullptr, NodeEvent::Level::kInfo,
          fmt::format("status {} -> {}", to_string(published_status_), to_string(status)));
    published_status_ = status;
  }
  silence_.on_odometry(now_mono_us, pose_.utime);
  published(status, now_mono_us);
  return &pose_;
}

bool FusionNode::fix_acceptable(const LaserFixInput& input, int64_t host_utime) {
  // Every LASER_POSE, with or without a pose, is one message of the solver's stream.
  const StampVerdict verdict = fix_stamps_.check(input.utime, host_utime);
  if (!stamp_accepted(verdict)) {
    reject(fix_stamp_counter(verdict),
           fmt::format("LASER_POSE at utime {} refused: stamp {} ({} us from the stream's clock)",
                       input.utime, to_string(verdict), -fix_stamps_.last_deviation_us()));
    return false;
  }
  if (verdict == StampVerdict::kReanchored) {
    event(fix_stamp_counter(verdict), NodeEvent::Level::kWarn,
          "LASER_POSE clock stepped: the stream's stamps are believed from here");
  }
  for (int64_t missing = fix_gaps_.on_stamp(input.utime); missing > 0; --missing)
    event("gap_laser_pose_messages");
  if (input.status == FixStatus::kNoPose) {
    event("fixes_unusable");
    return false;
  }
  const InputProblem problem = check_fix_values(input);
  if (problem != InputProblem::kNone) {
    reject(fix_value_counter(problem), fmt::format("LASER_POSE at utime {} refused: {} pose or covariance",
                                                   input.utime, to_string(problem)));
    return false;
  }
  return true;
}

std::optional<FusionOutput> FusionNode::on_fix(const LaserFixInput& input, int64_t now_mono_us,
                                               int64_t host_utime) {
  events_.clear();
  now_mono_us_ = now_mono_us;
  if (!fix_acceptable(input, host_utime)) return std::nullopt;
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
    published(FusionStatus::kDegraded, now_mono_us);
  }
  if (config_.measurements == FusionMeasurements::kDetections && !fusion_.needs_initialisation()) {
    const bool matches_flowing =
        last_matches_mono_us_ >= 0 && now_mono_us - last_matches_mono_us_ <= kMatchesSilentUs;
    if (matches_flowing) {
      event("fixes_left_to_detections");  // the scan's detections correct the estimate themselves
      return out;
    }
    if (!fixes_in_place_of_matches_) {
      fixes_in_place_of_matches_ = true;
      event(nullptr, NodeEvent::Level::kWarn,
            "no REFLECTOR_MATCHES for 0.2 s: LASER_POSE fixes correct the estimate until matches come again");
    }
    event("fixes_used_without_matches");
  }
  const FixResult result = fusion_.add_fix(*fix);
  count_fix_result(result);
  if (result == FixResult::kAccepted || result == FixResult::kInitialised)
    reflectors_used_ = input.reflectors_used;
  if (result == FixResult::kInitialised) {
    const Pose2& p = input.map_T_robot;
    if (fusion_.start_agreeing_fixes() > 0) {
      event("initialisations_from_degraded_fixes", NodeEvent::Level::kWarn,
            fmt::format(
                "initialised from {} agreeing DEGRADED fixes over {:.2f} s (no OK fix: fewer than the "
                "solver's reflectors for OK in view), the last at utime {}: ({:.3f}, {:.3f}, {:.4f})",
                fusion_.start_agreeing_fixes(), fusion_.start_span_s(), input.utime, p.x, p.y, p.theta));
    } else {
      event(nullptr, NodeEvent::Level::kInfo,
            fmt::format("initialised from the fix at utime {}: ({:.3f}, {:.3f}, {:.4f})", input.utime, p.x,
                        p.y, p.theta));
    }
  }
  return out;
}

void FusionNode::on_matches(const MatchesInput& input, int64_t now_mono_us, int64_t host_utime) {
  events_.clear();
  now_mono_us_ = now_mono_us;
  if (const InputFault fault = check_matches(input.detections, input.matches)) {
    NodeEvent e = match_checks_.rejected(fault.reason, fault.detail, host_utime);
    reject(e.counter, std::move(e.log));
    return;
  }
  if (!match_checks_.stamp_accepted(input.utime, host_utime, events_)) {
    last_rejection_ = events_.back().counter;
    last_rejection_mono_us_ = now_mono_us;
    return;
  }
  match_checks_.accepted(host_utime);
  last_matches_mono_us_ = now_mono_us;
  if (fixes_in_place_of_matches_) {
    fixes_in_place_of_matches_ = false;
    event(nullptr, NodeEvent::Level::kInfo, "REFLECTOR_MATCHES again: detections correct the estimate");
  }
  for (int64_t missing = match_checks_.missing_before(input.scan_counter, input.utime, events_); missing > 0;
       --missing)
    event(match_checks_.gap_counter());
  if (!input.matcher_ok) {
    event("scans_unusable");  // the matcher's AMBIGUOUS or LOST: no association to trust
    return;
  }
  scan_.utime = input.utime;
  scan_.detections.clear();
  for (const ReflectorMatch& m : input.matches) {
    const ReflectorDetection& d = input.detections[static_cast<size_t>(m.detection_index)];
    scan_.detections.push_back({d.laser_p_center, d.covariance, m.map_p_center, m.map_id});
  }
  const ScanResult result = fusion_.add_detections(scan_);
  switch (result.result) {
    case FixResult::kAccepted:
      event("scans_accepted");
      reflectors_used_ = result.accepted;
      break;
    case FixResult::kRejectedGate:
      event("scans_rejected_gate", NodeEvent::Level::kDebug,
            fmt::format("scan at utime {} refused: {} of {} detections outside the gate", input.utime,
                        result.rejected, result.rejected + result.accepted));
      break;
    case FixResult::kWaitingForGood:
      event("scans_waiting_for_fix");  // the filter starts from the solver's next OK fix, or agreeing
                                       // DEGRADED ones
      break;
    case FixResult::kAheadOfOdometry:
      reject("rejected_matches_ahead_of_odometry",
             fmt::format("REFLECTOR_MATCHES more than {:.1f} s ahead of the latest ODOMETRY: refused",
                         config_.fusion.history));
      break;
    case FixResult::kTooOld:
      event("scans_too_old");
      break;
    case FixResult::kDeferred:
      event("scans_deferred");
      break;
    case FixResult::kInitialised:
      break;
  }
  for (int i = 0; i < result.rejected && result.result == FixResult::kAccepted; ++i)
    event("detections_rejected_gate");
  const std::pair<double, int> nis = fusion_.take_detection_nis();
  if (nis.second > 0) {
    const double mean = nis.first / nis.second;
    nis_mean_ = nis_mean_ == 0.0 ? mean : nis_mean_ + 0.02 * (mean - nis_mean_);
  }
}

FusionHealth FusionNode::health(int64_t now_mono_us) const {
  if (last_output_mono_us_ < 0 || now_mono_us - last_output_mono_us_ >= kSilentOutputUs) {
    if (last_rejection_ == nullptr || now_mono_us - last_rejection_mono_us_ >= kSilentOutputUs)
      return {false, "no POSE published for 1 s: no usable ODOMETRY"};
    return {false, fmt::format("no POSE published for 1 s: input refused ({})", last_rejection_)};
  }
  return fusion_health(output_status_);
}

}  // namespace refloc
