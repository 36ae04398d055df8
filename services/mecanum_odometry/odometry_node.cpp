#include "mecanum_odometry/odometry_node.hpp"

#include <fmt/format.h>

namespace refloc {

OdometryNode::OdometryNode(const RobotConfig& robot, const OdometryServiceConfig& config)
    : config_(config), odometry_(robot, config.odometry) {}

const OdometryEstimate* OdometryNode::on_encoders(const EncoderReading& reading, int64_t now_mono_us) {
  events_.clear();
  last_sample_mono_us_ = now_mono_us;
  switch (odometry_.add_sample(reading.utime, reading.ticks)) {
    case EncoderSampleResult::kOutOfOrder:
      events_.push_back(counted("out_of_order_samples"));
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
  const bool fresh = last_sample_mono_us_ > 0 && now_mono_us - last_sample_mono_us_ < kSilenceUs;
  if (fresh) return {true, ""};
  return {false, "no " + config_.input_channel + " for 1 s"};
}

}  // namespace refloc
