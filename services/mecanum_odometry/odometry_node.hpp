#pragma once
// The mecanum_odometry service without LCM: each WHEEL_ENCODERS sample in, the
// ODOMETRY estimate to publish (or nothing for a refused sample), the heartbeat
// counters and warnings it causes, and the heartbeat state.
//
// A sample's stamp is judged first by a StampGuard (against the host clock through
// the stream's learned offset): one stamped an hour ahead, at INT64_MAX or in the
// past is refused and counted (rejected_wheel_encoders_stamp_*) and cannot make every
// later sample look out of order; a clock step that persists is believed
// (reanchored_wheel_encoders) and integration restarts from that sample's counts.
// Counts are int32 and cannot be non-finite; absurd jumps are the wheel-speed bound's
// (implausible_samples). Health is judged by output: OK only while ODOMETRY was
// published within the last second.

#include "common/node_event.hpp"
#include "common/robot_config.hpp"
#include "common/stamp_guard.hpp"
#include "mecanum_odometry/mecanum_odometry.hpp"
#include "mecanum_odometry/odometry_config_file.hpp"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// One WHEEL_ENCODERS message (wheel_encoders_t) as a plain struct.
struct EncoderReading {
  int64_t utime = 0;               ///< [us]
  std::array<int32_t, 4> ticks{};  ///< cumulative counts, front-left, front-right, rear-right, rear-left
};

struct OdometryHealth {
  bool ok = false;
  std::string detail;  ///< why not OK
};

class OdometryNode {
 public:
  /// No sample, or no ODOMETRY published, for this long: the heartbeat says DEGRADED [us].
  static constexpr int64_t kSilenceUs = 1'000'000;

  OdometryNode(const RobotConfig& robot, const OdometryServiceConfig& config);

  /// A sample arriving at now_mono_us [monotonic us], host_utime the host's wall clock
  /// [us]; the estimate to publish, or nullptr when the sample is refused.
  const OdometryEstimate* on_encoders(const EncoderReading& reading, int64_t now_mono_us, int64_t host_utime);
  /// Counters and warnings of the last on_encoders call.
  const std::vector<NodeEvent>& events() const { return events_; }
  /// The heartbeat state at now_mono_us.
  OdometryHealth health(int64_t now_mono_us) const;

 private:
  const OdometryEstimate* integrate(const EncoderReading& reading);
  void reject(const char* counter, std::string log, int64_t now_mono_us);

  OdometryServiceConfig config_;
  RobotConfig robot_;
  MecanumOdometry odometry_;
  StampGuard stamps_;
  int64_t last_sample_mono_us_ = 0;
  int64_t last_published_mono_us_ = -1;
  const char* last_rejection_ = nullptr;
  int64_t last_rejection_mono_us_ = 0;
  std::vector<NodeEvent> events_;
};

}  // namespace refloc
