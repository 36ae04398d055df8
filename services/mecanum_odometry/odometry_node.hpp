#pragma once
// The mecanum_odometry service without LCM: each WHEEL_ENCODERS sample in, the
// ODOMETRY estimate to publish (or nothing for an out-of-order sample), the
// heartbeat counters and warnings it causes, and the heartbeat state (OK while
// samples arrive, DEGRADED after a second without one).

#include "common/node_event.hpp"
#include "common/robot_config.hpp"
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
  /// No sample for this long: the heartbeat says DEGRADED [us].
  static constexpr int64_t kSilenceUs = 1'000'000;

  OdometryNode(const RobotConfig& robot, const OdometryServiceConfig& config);

  /// A sample arriving at now_mono_us [monotonic us]; the estimate to publish, or
  /// nullptr when the sample is out of order (nothing published).
  const OdometryEstimate* on_encoders(const EncoderReading& reading, int64_t now_mono_us);
  /// Counters and warnings of the last on_encoders call.
  const std::vector<NodeEvent>& events() const { return events_; }
  /// The heartbeat state at now_mono_us.
  OdometryHealth health(int64_t now_mono_us) const;

 private:
  OdometryServiceConfig config_;
  MecanumOdometry odometry_;
  int64_t last_sample_mono_us_ = 0;
  std::vector<NodeEvent> events_;
};

}  // namespace refloc
