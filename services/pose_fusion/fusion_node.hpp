#pragma once
// The pose_fusion service without LCM: ODOMETRY and LASER_POSE in, in arrival
// order; POSE out once per odometry message (and, while odometry is silent, once
// per new usable fix, as DEGRADED), with the heartbeat counters to bump, the log
// lines to write and the heartbeat state. main.cpp only converts messages.

#include "common/node_event.hpp"
#include "common/odometry_noise.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_fusion/laser_fix_input.hpp"
#include "pose_fusion/odometry_continuity.hpp"
#include "pose_fusion/odometry_silence.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace refloc {

/// A POSE to publish (the plain form of pose2d_t on POSE).
struct FusionOutput {
  int64_t utime = 0;  ///< [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2, m rad, rad^2]
  FusionStatus status = FusionStatus::kInitializing;
  int32_t reflectors_used = 0;  ///< of the latest accepted fix
};

/// The HEARTBEAT state after an odometry message: OK only while the filter is OK.
struct FusionHealth {
  bool ok = false;
  std::string detail;  ///< the fusion status when not OK
};
FusionHealth fusion_health(FusionStatus status);

/// The heartbeat counter a fix result bumps.
const char* fix_result_counter(FixResult result);

class FusionNode {
 public:
  /// noise: the robot's odometry increment noise (robot.json).
  FusionNode(const FusionServiceConfig& config, const OdometryNoise& noise);

  /// One ODOMETRY message arriving at now_mono_us [monotonic us]; the POSE to publish.
  const FusionOutput& on_odometry(const OdometrySample& sample, int64_t now_mono_us);
  /// One LASER_POSE message arriving at now_mono_us; a POSE to publish while odometry is silent.
  std::optional<FusionOutput> on_fix(const LaserFixInput& input, int64_t now_mono_us);

  /// Counters and log lines of the last on_odometry / on_fix call.
  const std::vector<NodeEvent>& events() const { return events_; }
  /// After the latest odometry message.
  FusionHealth health() const { return fusion_health(published_status_); }
  const PoseFusion& fusion() const { return fusion_; }

 private:
  void apply_step(const OdometrySample& sample, const OdometryStep& step);
  void count_fix_result(FixResult result);
  void event(const char* counter, NodeEvent::Level level = NodeEvent::Level::kDebug, std::string log = {});

  OdometryNoise noise_;
  PoseFusion fusion_;
  OdometryContinuity continuity_;
  OdometrySilence silence_;
  int32_t reflectors_used_ = 0;
  FusionStatus published_status_ = FusionStatus::kInitializing;
  FusionOutput pose_;
  std::vector<NodeEvent> events_;
};

}  // namespace refloc
