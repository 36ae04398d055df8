#pragma once
// The pose_fusion service without LCM: ODOMETRY, REFLECTOR_MATCHES and LASER_POSE in,
// in arrival order; POSE out once per accepted odometry message (and, while odometry is
// silent, once per new usable fix, as DEGRADED), with the heartbeat counters to bump, the
// log lines to write and the heartbeat state. main.cpp only converts messages. With
// measurements "detections" the matched detections correct the estimate and LASER_POSE
// only (re-)initialises it; with "laser_pose" the fixes do both and matches are not read.
//
// Every message is judged before the filter sees it: its stamp by a StampGuard per
// stream (against the host clock through the stream's learned offset), then its
// values (fusion_input_checks.hpp); odometry also by OdometryContinuity's jump check.
// A refused message is skipped whole, counted as rejected_<input>_<reason> with a
// warning, and publishes nothing. Missing messages of either periodic stream are
// counted as gap_<input>_messages. Health is judged by what is published: no POSE
// for kSilentOutputUs is DEGRADED whatever arrives.

#include "common/input_stream_checks.hpp"
#include "common/node_event.hpp"
#include "common/odometry_noise.hpp"
#include "common/reflector_detection.hpp"
#include "common/stamp_guard.hpp"
#include "pose_fusion/fusion_config_file.hpp"
#include "pose_fusion/laser_fix_input.hpp"
#include "pose_fusion/odometry_continuity.hpp"
#include "pose_fusion/odometry_silence.hpp"
#include "pose_fusion/pose_fusion.hpp"
#include "pose_fusion/stream_gap_counter.hpp"

#include <algorithm>
#include <cmath>
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

/// One REFLECTOR_MATCHES message (reflector_matches_t) as plain structs.
struct MatchesInput {
  int64_t utime = 0;  ///< the scan's time [us]
  int64_t scan_counter = 0;
  bool matcher_ok = false;  ///< the matcher's status is OK (AMBIGUOUS, LOST: no association to use)
  std::vector<ReflectorDetection> detections;
  std::vector<ReflectorMatch> matches;  ///< detection_index into detections
};

/// The HEARTBEAT state: OK only while POSE is published and its status is OK.
struct FusionHealth {
  bool ok = false;
  std::string detail;  ///< the fusion status, or why nothing is published, when not OK
};
FusionHealth fusion_health(FusionStatus status);

/// The heartbeat counter a fix result bumps.
const char* fix_result_counter(FixResult result);

class FusionNode {
 public:
  /// No POSE published this long: DEGRADED [us].
  static constexpr int64_t kSilentOutputUs = 1'000'000;
  /// With measurements "detections": no REFLECTOR_MATCHES received this long (ten scans at
  /// 50 Hz; matcher restarting, a solver fed from elsewhere): LASER_POSE fixes correct the
  /// estimate instead, until matches come again [us]. Never both for one scan: fixes start
  /// only after this silence, and stop at the first matches message.
  static constexpr int64_t kMatchesSilentUs = 200'000;

  /// noise: the robot's odometry increment noise (robot.json).
  FusionNode(const FusionServiceConfig& config, const OdometryNoise& noise);

  /// One ODOMETRY message arriving at now_mono_us [monotonic us], host_utime the host's
  /// wall clock [us]; the POSE to publish, or nullptr when the message was refused.
  const FusionOutput* on_odometry(const OdometrySample& sample, int64_t now_mono_us, int64_t host_utime);
  /// One LASER_POSE message; a POSE to publish while odometry is silent.
  std::optional<FusionOutput> on_fix(const LaserFixInput& input, int64_t now_mono_us, int64_t host_utime);
  /// One REFLECTOR_MATCHES message (measurements "detections"); never publishes by itself.
  void on_matches(const MatchesInput& input, int64_t now_mono_us, int64_t host_utime);

  /// The heartbeat gauges (name, integer value): the range bias, the odometry calibration and
  /// the scans' time offset the filter estimates, and the mean squared Mahalanobis distance of accepted
  /// detections.
  template <typename Set>
  void for_each_gauge(Set&& set) const {
    const FusionState& s = fusion_.state();
    const auto sigma = [&](int i) { return std::sqrt(std::max(s.covariance(i, i), 0.0)); };
    set("range_bias_um", std::llround(s.range_bias_m * 1e6));
    set("range_bias_sigma_um", std::llround(sigma(StateIndex::kRangeBias) * 1e6));
    set("odometry_error_xx_ppm", std::llround(s.odometry_error(0, 0) * 1e6));
    set("odometry_error_yy_ppm", std::llround(s.odometry_error(1, 1) * 1e6));
    set("odometry_error_turn_ppm", std::llround(s.odometry_error(2, 2) * 1e6));
    set("odometry_error_turn_per_x_ppm", std::llround(s.odometry_error(2, 0) * 1e6));
    set("scan_time_offset_us", std::llround(s.scan_time_offset_s * 1e6));
    set("scan_time_offset_sigma_us", std::llround(sigma(StateIndex::kScanTimeOffset) * 1e6));
    set("detection_nis_milli", std::llround(nis_mean_ * 1e3));
    set("noise_inflation_milli", std::llround(fusion_.noise_inflation() * 1e3));
  }
  /// Counters and log lines of the last on_odometry / on_fix call.
  const std::vector<NodeEvent>& events() const { return events_; }
  /// The heartbeat state at now_mono_us, from what was published.
  FusionHealth health(int64_t now_mono_us) const;
  const PoseFusion& fusion() const { return fusion_; }

 private:
  bool odometry_acceptable(const OdometrySample& sample, int64_t host_utime);
  bool fix_acceptable(const LaserFixInput& input, int64_t host_utime);
  void apply_step(const OdometrySample& sample, const OdometryStep& step);
  void count_fix_result(FixResult result);
  void reject(const char* counter, std::string log);
  void published(FusionStatus status, int64_t now_mono_us);
  void event(const char* counter, NodeEvent::Level level = NodeEvent::Level::kDebug, std::string log = {});

  FusionServiceConfig config_;
  OdometryNoise noise_;
  PoseFusion fusion_;
  OdometryContinuity continuity_;
  OdometrySilence silence_;
  StampGuard odometry_stamps_;
  StampGuard fix_stamps_;
  StreamGapCounter odometry_gaps_;
  StreamGapCounter fix_gaps_;
  InputStreamChecks match_checks_{"matches", chain_stream_stamp_limits()};
  DetectionScan scan_;
  int64_t last_matches_mono_us_ = -1;       ///< last REFLECTOR_MATCHES that passed the input checks
  bool fixes_in_place_of_matches_ = false;  ///< for the log: LASER_POSE is correcting
  double nis_mean_ = 0.0;  ///< moving mean over ~50 scans of accepted detections' Mahalanobis^2
  int32_t reflectors_used_ = 0;
  FusionStatus published_status_ = FusionStatus::kInitializing;  ///< of the filter, for the log
  FusionStatus output_status_ = FusionStatus::kInitializing;     ///< of the latest POSE published
  int64_t last_output_mono_us_ = -1;
  int64_t now_mono_us_ = 0;  ///< of the call in progress
  const char* last_rejection_ = nullptr;
  int64_t last_rejection_mono_us_ = 0;
  FusionOutput pose_;
  std::vector<NodeEvent> events_;
};

}  // namespace refloc
