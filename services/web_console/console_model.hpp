#pragma once
// Turns what the console subscribes to into JSON frames for the page (docs: the README's
// "Frames"). Runs on the LCM thread; never blocks. Scans and poses are decimated by their own
// stamps; trails are kept here and handed to clients that connect later as snapshots.

#include "common/reflector_map.hpp"
#include "web_console/console_config.hpp"
#include "web_console/console_frame.hpp"
#include "web_console/console_inputs.hpp"
#include "web_console/pose_trail.hpp"
#include "web_console/rate_decimator.hpp"

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace refloc {

/// The console's own state for its HEARTBEAT.
struct ConsoleState {
  bool ok = true;
  std::string detail;  ///< why not OK
};

/// The pose channels the console draws.
enum class PoseSource { kPose, kLaserPose, kGroundTruth };
const char* pose_source_name(PoseSource source);  ///< "POSE", "LASER_POSE", "GROUND_TRUTH"

class ConsoleModel {
 public:
  ConsoleModel(const ConsoleModelConfig& config, ReflectorMap map, bool control_enabled);

  /// The map frame: reflectors with ids and radii, occluders, the map's id and version.
  ConsoleFrame map_frame() const;
  /// What the page needs to know about the console itself (control enabled, rates).
  ConsoleFrame console_frame() const;

  std::optional<ConsoleFrame> on_scan(const ConsoleScan& scan);  ///< nullopt: decimated away
  /// Detections and matches reach the page at scan_rate_hz too, by their scan's stamp: the same
  /// scans as on_scan lets through.
  std::optional<ConsoleFrame> on_detections(const ConsoleDetections& detections);
  std::optional<ConsoleFrame> on_clusters(const ConsoleClusters& clusters);
  std::optional<ConsoleFrame> on_matches(const ConsoleMatches& matches);
  std::optional<ConsoleFrame> on_pose(PoseSource source, const ConsolePose& pose);
  ConsoleFrame on_goal(const ConsoleGoal& goal);
  ConsoleFrame on_nav_status(const ConsoleNavStatus& status);
  /// Kept per service for later clients, at most kMaxKeptServices of them (a peer inventing
  /// names must not grow the console); a heartbeat beyond is sent, not kept.
  ConsoleFrame on_heartbeat(const ConsoleHeartbeat& heartbeat);
  static constexpr size_t kMaxKeptServices = 64;
  ConsoleFrame on_map_health(const ConsoleMapHealth& health);
  /// Localization at a glance, once a second: LASER_POSE fixes per second (all, and OK) since the
  /// last call at now_mono_us [monotonic us], and the latest POSE and REFLECTOR_MATCHES status.
  ConsoleFrame localization_frame(int64_t now_mono_us);
  /// DEGRADED while the scan or the POSE channel has been silent for more than kSilentAfterUs
  /// (a page that shows nothing must say why: a wrong channel name, a stopped driver or fusion);
  /// call about once a second with the monotonic clock [us].
  ConsoleState state(int64_t now_mono_us);
  static constexpr int64_t kSilentAfterUs = 3'000'000;
  /// One snapshot frame per trail, kept for clients that connect later (not sent now).
  std::vector<ConsoleFrame> trail_frames() const;

  const ReflectorMap& map() const { return map_; }
  size_t trail_size(PoseSource source) const { return trails_[static_cast<int>(source)].size(); }
  int64_t scans_skipped() const { return scans_skipped_; }

 private:
  ConsoleModelConfig config_;
  ReflectorMap map_;
  bool control_enabled_;
  RateDecimator scan_rate_;
  RateDecimator detections_rate_;
  RateDecimator clusters_rate_;
  RateDecimator matches_rate_;
  std::vector<RateDecimator> pose_rates_;
  std::vector<PoseTrail> trails_;
  /// The latest OK matches' map_T_laser: where the page draws scans and detections.
  std::optional<std::array<double, 3>> map_T_laser_;
  int64_t scans_skipped_ = 0;
  int64_t scans_in_ = 0;  ///< every scan, decimated or not
  int64_t poses_in_ = 0;  ///< every POSE
  struct Silence {
    int64_t count_seen = -1;  ///< the count at the last state() call
    int64_t changed_us = -1;  ///< when it last changed [monotonic us]
  };
  Silence scan_silence_, pose_silence_;
  std::set<std::string> kept_services_;
  int64_t fixes_ = 0;     ///< LASER_POSE messages since the last localization_frame
  int64_t ok_fixes_ = 0;  ///< of them with status OK
  int64_t last_localization_mono_us_ = -1;
  std::string pose_status_ = "none";
  std::string matches_status_ = "none";
};

}  // namespace refloc
