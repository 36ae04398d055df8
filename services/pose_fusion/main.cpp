// pose_fusion: ODOMETRY (odometry_t) + LASER_POSE (pose2d_t) -> POSE (pose2d_t),
// one output per odometry message.

#include "common/clock.hpp"
#include "common/json_config.hpp"
#include "common/lcm_conversions.hpp"
#include "common/robot_config.hpp"
#include "common/service_command_line.hpp"
#include "common/service_runtime.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_fusion/odometry_continuity.hpp"
#include "pose_fusion/odometry_silence.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>

#include <cmath>
#include <optional>

namespace refloc {
namespace {

int8_t to_status(FusionStatus s) {
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

/// A fix the filter can use, or nothing (status unusable, covariance not positive).
std::optional<PoseFix> to_fix(const pose2d_t& msg) {
  PoseFix fix;
  if (msg.status == pose2d_t::STATUS_OK) {
    fix.quality = FixQuality::kGood;
  } else if (msg.status == pose2d_t::STATUS_DEGRADED) {
    fix.quality = FixQuality::kUsable;
  } else {
    return std::nullopt;
  }
  fix.utime = msg.utime;
  fix.map_T_robot = {msg.x, msg.y, msg.theta};
  fix.covariance = covariance_from_lcm(msg.covariance);
  if (!std::isfinite(msg.x) || !std::isfinite(msg.y) || !std::isfinite(msg.theta) ||
      !fix.covariance.allFinite() || fix.covariance.diagonal().minCoeff() <= 0.0) {
    return std::nullopt;
  }
  return fix;
}

int run(const std::string& lcm_url, const std::string& robot_path, const std::string& config_path) {
  const OdometryNoise odometry_noise = load_robot_config(robot_path).odometry_noise;
  FusionServiceConfig config;
  if (!config_path.empty()) {
    const JsonConfig file = JsonConfig::load_file(config_path);
    config = parse_fusion_service_config(file);
    file.reject_unknown_keys();
  }
  ServiceRuntime runtime("pose_fusion", lcm_url);
  PoseFusion fusion(config.fusion);
  OdometryContinuity continuity(config.continuity);
  OdometrySilence silence(config.odometry_timeout);
  int32_t reflectors_used = 0;
  FusionStatus published_status = FusionStatus::kInitializing;

  const auto count_fix_result = [&](FixResult result) {
    switch (result) {
      case FixResult::kAccepted:
        ++runtime.counter("fixes_accepted");
        break;
      case FixResult::kInitialised:
        ++runtime.counter("initialisations");
        break;
      case FixResult::kRejectedGate:
        ++runtime.counter("fixes_rejected_gate");
        spdlog::debug("fix rejected, Mahalanobis^2 {:.1f}", fusion.last_mahalanobis_squared());
        break;
      case FixResult::kTooOld:
        ++runtime.counter("fixes_too_old");
        break;
      case FixResult::kWaitingForGood:
        ++runtime.counter("fixes_not_good_enough_to_start");
        break;
      case FixResult::kDeferred:
        ++runtime.counter("fixes_deferred");
        break;
    }
  };

  runtime.subscribe<odometry_t>(config.odometry_channel, [&](const odometry_t& msg) {
    const OdometryStep step = continuity.next({msg.utime, {msg.x, msg.y, msg.theta}, msg.distance});
    switch (step.kind) {
      case OdometryStepKind::kFirst:
        break;
      case OdometryStepKind::kBackwards:
        // A restarted odometry service on another clock: take the next step from here.
        ++runtime.counter("odometry_restarts");
        spdlog::warn("ODOMETRY went back in time by {:.3f} s: new odometry frame", -step.gap);
        break;
      case OdometryStepKind::kContinuous:
        fusion.add_odometry(msg.utime, step.delta, increment_covariance(step.delta, odometry_noise));
        break;
      case OdometryStepKind::kSeam:
        ++runtime.counter(step.restarted ? "odometry_restarts" : "odometry_gaps");
        spdlog::warn(
            "ODOMETRY {} after {:.3f} s: motion meanwhile unobserved, waiting for a fix to re-anchor",
            step.restarted ? "restarted" : "resumed", step.gap);
        fusion.add_odometry_seam(msg.utime, step.delta,
                                 increment_covariance(step.delta, odometry_noise) + step.unobserved_q);
        break;
    }
    for (const FixResult r : fusion.deferred_results()) count_fix_result(r);
    const FusionStatus status = fusion.status(msg.utime);
    if (status != published_status) {
      spdlog::info("status {} -> {}", to_string(published_status), to_string(status));
      published_status = status;
    }
    pose2d_t out{};
    out.utime = msg.utime;
    const PoseEstimate& e = fusion.estimate();
    out.x = e.map_T_robot.x;
    out.y = e.map_T_robot.y;
    out.theta = e.map_T_robot.theta;
    covariance_to_lcm(e.covariance, out.covariance);
    out.status = to_status(status);
    out.reflectors_used = reflectors_used;
    out.residual = 0.0;
    runtime.publish(config.output_channel, out);
    silence.on_odometry(monotonic_us(), out.utime);
    runtime.set_state(status == FusionStatus::kOk ? heartbeat_t::STATE_OK : heartbeat_t::STATE_DEGRADED,
                      status == FusionStatus::kOk ? "" : to_string(status));
  });

  runtime.subscribe<pose2d_t>(config.fix_channel, [&](const pose2d_t& msg) {
    const std::optional<PoseFix> fix = to_fix(msg);
    if (!fix) {
      ++runtime.counter("fixes_unusable");
      return;
    }
    if (silence.publish_fix(monotonic_us(), msg.utime)) {
      // No ODOMETRY (its service restarting?): the fix itself, DEGRADED, rather than no POSE at all.
      pose2d_t out = msg;
      out.status = pose2d_t::STATUS_DEGRADED;
      out.residual = 0.0;
      runtime.publish(config.output_channel, out);
      ++runtime.counter("fixes_published_without_odometry");
    }
    const FixResult result = fusion.add_fix(*fix);
    count_fix_result(result);
    if (result == FixResult::kAccepted || result == FixResult::kInitialised)
      reflectors_used = msg.reflectors_used;
    if (result == FixResult::kInitialised) {
      spdlog::info("initialised from the fix at utime {}: ({:.3f}, {:.3f}, {:.4f})", msg.utime, msg.x, msg.y,
                   msg.theta);
    }
  });
  return runtime.run();
}

}  // namespace
}  // namespace refloc

int main(int argc, char** argv) {
  refloc::ServiceCommandLine cli(
      "pose_fusion",
      "EKF fusion of wheel odometry and delayed laser pose fixes: ODOMETRY + LASER_POSE -> POSE", "");
  cli.add_robot_option("robot file (JSON): the odometry noise model");
  return cli.run(argc, argv, [&] { return refloc::run(cli.lcm_url, cli.robot_path, cli.config_path); });
}
