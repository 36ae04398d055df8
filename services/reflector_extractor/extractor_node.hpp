#pragma once
// The reflector_extractor service without LCM: odometry, laser fixes and scans in, in time
// order; per scan the detections (motion-compensated with fresh odometry, else with the
// twist of recent LASER_POSE fixes), the extraction statistics and the heartbeat counters. main.cpp and
// refloc-eval both run this. Every message is judged first (extractor_input_checks, then its stamp and, for
// scans, the scan counter: common/input_stream_checks.hpp); a rejected one changes nothing.

#include "common/input_stream_checks.hpp"
#include "common/node_event.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/motion_compensator.hpp"
#include "reflector_extractor/no_reflector_watch.hpp"
#include "reflector_extractor/rssi_scale.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

struct ExtractorOutput {
  /// false: the scan was rejected (events say why); there is nothing to publish.
  bool accepted = false;
  std::vector<NodeEvent> events;  ///< rejection, clock re-anchor, counter reset, gap
  int64_t missing_scans = 0;      ///< scan counters missing before this scan
  int64_t utime = 0;              ///< the scan's (first beam) [us]
  uint32_t scan_counter = 0;
  std::vector<ReflectorDetection> detections;  ///< in the laser frame at utime
  ExtractionStats stats;
  /// Every bright cluster with its outcome (REFLECTOR_CLUSTERS); the accepted ones are detections.
  std::vector<ClusterRecord> clusters;
  double energy_threshold_8bit = 0.0;  ///< the extractor's [8-bit scale]
  double energy_threshold_raw = 0.0;   ///< the same on this scan's own RSSI scale
  bool rssi_read_as_8bit = false;      ///< a 16-bit channel read as 8-bit values
  CompensationOutcome compensation = CompensationOutcome::kOff;

  /// Calls bump(name, increment) for each heartbeat counter an accepted scan touches (a
  /// counter first appears when first touched, so the set touched matters, not only the
  /// sums). A rejected scan's counters are in events.
  template <class Bump>
  void for_each_counter(Bump&& bump) const {
    if (!accepted) return;
    bump("gap_scan_messages", missing_scans);
    if (compensation == CompensationOutcome::kOdometry) bump("scans_compensated_odometry", 1);
    if (compensation == CompensationOutcome::kFixes) bump("scans_compensated_fixes", 1);
    if (compensation == CompensationOutcome::kNoMotionSource) bump("scans_without_motion_source", 1);
    if (compensation == CompensationOutcome::kFixes || compensation == CompensationOutcome::kNoMotionSource)
      bump("scans_without_fresh_odometry", 1);
    bump("rejected_too_few_beams", stats.rejected_too_few_beams);
    bump("rejected_shape", stats.rejected_too_wide + stats.rejected_too_narrow + stats.rejected_not_round +
                               stats.rejected_radius + stats.rejected_fit_failed);
    bump("rejected_occluded", stats.rejected_occluded);
    if (detections.empty()) bump("scans_without_reflectors", 1);
  }
};

/// The heartbeat state: STARTING until any message came in; DEGRADED while scans come but
/// none was usable for over a second, or while usable scans brought no reflector for over
/// no_reflector_timeout_s (the reason in detail); else OK. detail also names an RSSI scale
/// read as 8-bit in the 16-bit channel.
struct ExtractorHealth {
  enum class State { kStarting, kOk, kDegraded };
  State state = State::kStarting;
  std::string detail;
  /// Heartbeat gauge rssi_scale_8bit: 1 while the 16-bit channel is read as 8-bit, 0 after a
  /// switch back; -1 (not shown) until it was ever read so.
  int rssi_scale_8bit = -1;
};

class ExtractorNode {
 public:
  /// robot_T_laser: the laser mount (only motion compensation uses it).
  ExtractorNode(const ExtractorServiceConfig& config, const Pose2& robot_T_laser);

  /// One ODOMETRY sample at host wall-clock time host_utime [us]; the events of a rejected
  /// one (an invalid twist is never used for compensation). Valid until the next call.
  const std::vector<NodeEvent>& on_odometry(const OdometrySample& sample, int64_t host_utime);
  /// One LASER_POSE at host_utime [us] (motion compensation without odometry); fixes that
  /// are not OK are ignored, a rejected one returns its event. Valid until the next call.
  const std::vector<NodeEvent>& on_laser_pose(const LaserPoseFix& fix, int64_t host_utime);
  /// One scan at host_utime [us]; the reference stays valid until the next call.
  const ExtractorOutput& on_scan(const LaserScan& scan, int64_t host_utime);

  /// Offline (logs, simulations): each message's own stamp is the host clock, so stamps
  /// are judged only against the stream's history.
  const std::vector<NodeEvent>& on_odometry(const OdometrySample& sample) {
    return on_odometry(sample, sample.utime);
  }
  const ExtractorOutput& on_scan(const LaserScan& scan) { return on_scan(scan, scan.utime); }
  const std::vector<NodeEvent>& on_laser_pose(const LaserPoseFix& fix) {
    return on_laser_pose(fix, fix.utime);
  }

  /// The state at host_utime [us], for a heartbeat; input_channel names the scans' channel.
  ExtractorHealth health(int64_t messages_in, int64_t host_utime, const std::string& input_channel) const;

  const ReflectorExtractor& extractor() const { return extractor_; }
  /// How the 16-bit RSSI channel is read now.
  RssiScale rssi_scale() const { return rssi_scale_.scale(); }

 private:
  ReflectorExtractor extractor_;
  MotionCompensator compensator_;
  RssiScaleDetector rssi_scale_;
  NoReflectorWatch no_reflector_;
  bool rssi_scale_was_8bit_ = false;
  BeamTable table_;
  // 1 s too: 0.1 s refused 150 good scans of a loaded hostile-bus run (issue 11).
  InputStreamChecks scan_checks_{"scan", chain_stream_stamp_limits()};
  InputStreamChecks odometry_checks_{"odometry", chain_stream_stamp_limits()};      // from mecanum_odometry
  InputStreamChecks laser_pose_checks_{"laser_pose", chain_stream_stamp_limits()};  // from pose_solver
  std::vector<NodeEvent> odometry_events_;
  std::vector<NodeEvent> laser_pose_events_;
  bool compensation_chosen_ = false;  ///< a scan was compensated (or not) already
  CompensationOutcome last_compensation_ = CompensationOutcome::kOff;
  ExtractorOutput output_;
};

}  // namespace refloc
