#include "mecanum_odometry/odometry_node.hpp"

#include "common/input_sanity.hpp"

#include <fmt/format.h>

namespace refloc {
namespace {

const char* stamp_counter(StampVerdict v) {
  switch (v) {
    case StampVerdict::kAhead:
      return "rejected_wheel_encoders_stamp_ahead";
    case StampVerdict::kBehind:
      return "rejected_wheel_encoders_stamp_behind";
    case StampVerdict::kNotIncreasing:
      return "rejected_wheel_encoders_stamp_not_increasing";
    case StampVerdict::kReanchored:
      return "reanchored_wheel_encoders";
    case StampVerdict::kAccepted:
      break;
  }
  return nullptr;
}

bool estimate_finite(const OdometryEstimate& e) {
  const Pose2& p = e.odom_T_robot;
  return all_finite({p.x, p.y, p.theta, e.twist.vx, e.twist.vy, e.twist.wz, e.distance, e.slip_indicator}) &&
         e.covariance.allFinite();
}

}  // namespace

OdometryNode::OdometryNode(const RobotConfig& robot, const OdometryServiceConfig& config)
    : config_(config), robot_(robot), odometry_(robot, config.odometry) {}

void OdometryNode::reject(const char* counter, std::string log, int64_t now_mono_us) {
  last_rejection_ = counter;
  last_rejection_mono_us_ = now_mono_us;
  events_.push_back({counter, NodeEvent::Level::kWarn, std::move(log)});
}

const OdometryEstimate* OdometryNode::on_encoders(const EncoderReading& reading, int64_t now_mono_us,
                                                  int64_t host_utime) {
  events_.clear();
  last_sample_mono_us_ = now_mono_us;
  const StampVerdict verdict = stamps_.check(reading.utime, host_utime);
  if (!stamp_accepted(verdict)) {
    reject(
        stamp_counter(verdict),
        fmt::format("{} at utime {} refused: stamp {} ({} us from the stream's clock)", config_.input_channel,
                    reading.utime, to_string(verdict), -stamps_.last_deviation_us()),
        now_mono_us);
    return nullptr;
  }
  if (verdict == StampVerdict::kReanchored) {
    events_.push_back({stamp_counter(verdict), NodeEvent::Level::kWarn,
                       fmt::format("{}: the encoder clock stepped; integration restarted from the new counts",
                                   config_.input_channel)});
    odometry_.restart_from(reading.utime, reading.ticks);
  }
  const OdometryEstimate* estimate =
      verdict == StampVerdict::kReanchored ? &odometry_.estimate() : integrate(reading);
  if (estimate == nullptr) return nullptr;
  if (!estimate_finite(*estimate)) {
    // Cannot happen from int32 counts and checked stamps; should it anyway, start over rather than publish
    // it.
    odometry_ = MecanumOdometry(robot_, config_.odometry);
    reject("estimate_resets_nonfinite", "the odometry estimate became non-finite: integration restarted",
           now_mono_us);
    return nullptr;
  }
  last_published_mono_us_ = now_mono_us;
  return estimate;
}

const OdometryEstimate* OdometryNode::integrate(const EncoderReading& reading) {
  switch (odometry_.add_sample(reading.utime, reading.ticks)) {
    case EncoderSampleResult::kOutOfOrder:  // the stamp guard lets none through; kept as a last line
      events_.push_back(counted("rejected_wheel_encoders_stamp_not_increasing"));
      return nullptr;
    case EncoderSampleResult::kGapRestart:
      events_.push_back({"gap_restarts", NodeEvent::Level::kWarn,
                         fmt::format("{}: gap in encoder samples, integration restarted from the new counts",
                                     config_.input_channel)});
      break;
    case EncoderSampleResult::kImplausible:
      events_.push_back({"implausible_samples", NodeEvent::Level::kWarn,
                         fmt::format("{}: wheel speed above {} rad/s, sample skipped", config_.input_channel,
                                     config_.odometry.max_plausible_wheel_speed)});
      break;
    case EncoderSampleResult::kFirstSample:
    case EncoderSampleResult::kIntegrated:
      break;
  }
  if (odometry_.estimate().slip_indicator > config_.slip_warning) events_.push_back(counted("slip_samples"));
  return &odometry_.estimate();
}

OdometryHealth OdometryNode::health(int64_t now_mono_us) const {
  const bool receiving = last_sample_mono_us_ > 0 && now_mono_us - last_sample_mono_us_ < kSilenceUs;
  if (!receiving) return {false, "no " + config_.input_channel + " for 1 s"};
  const bool publishing = last_published_mono_us_ >= 0 && now_mono_us - last_published_mono_us_ < kSilenceUs;
  if (publishing) return {true, ""};
  const bool refused = last_rejection_ != nullptr && now_mono_us - last_rejection_mono_us_ < kSilenceUs;
  return {false, fmt::format("{} received but no {} published for 1 s{}{}", config_.input_channel,
                             config_.output_channel, refused ? ": samples refused, " : "",
                             refused ? last_rejection_ : "")};
}

}  // namespace refloc
