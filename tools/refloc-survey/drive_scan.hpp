#pragma once
// The driving survey's input, read once: per scan its reflector detections (the
// reflector_extractor service's own node, with its motion compensation from ODOMETRY), the
// odometry pose at the scan's time and the diffuse echoes (walls, racks) for the occluders.
// Fed message by message in log order, as the service is fed; no LCM here (drive_log converts).

#include "common/laser_scan.hpp"
#include "common/odometry_sample.hpp"
#include "common/reflector_detection.hpp"
#include "common/se2.hpp"
#include "reflector_extractor/beam_table.hpp"
#include "reflector_extractor/extractor_config_file.hpp"
#include "reflector_extractor/extractor_node.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

/// One scan of a survey drive, everything in the laser frame at the scan's first-beam time.
struct DriveScan {
  int64_t utime = 0;             ///< first beam [us]
  Pose2 odom_T_robot;            ///< odometry at utime, interpolated [m, m, rad]
  double angle_increment = 0.0;  ///< the scan's beam step [rad]
  std::vector<ReflectorDetection> detections;
  /// Echoes below the extractor's energy threshold (walls, racks), each moved to utime with
  /// the odometry twist like the detections [m]; every diffuse_stride-th beam.
  std::vector<Eigen::Vector2f> laser_p_diffuse;
};

struct DriveScanCounts {
  int64_t scans = 0;                   ///< scans given
  int64_t scans_rejected = 0;          ///< refused by the extractor's input checks
  int64_t scans_without_odometry = 0;  ///< no odometry around their time: dropped
  int64_t odometry = 0;                ///< odometry samples given
  int64_t detections = 0;              ///< detections in the scans kept
};

struct DriveScanOptions {
  /// Odometry samples further apart than this around a scan leave it without a pose [s].
  double max_odometry_gap_s = 0.25;
  /// Keep every n-th diffuse beam: the occluder grid needs density, not every beam [-].
  int diffuse_stride = 2;
};

class DriveScanBuilder {
 public:
  /// extractor: the service's config file as read; robot_T_laser: the mount (compensation).
  DriveScanBuilder(const ExtractorServiceConfig& extractor, const Pose2& robot_T_laser,
                   const DriveScanOptions& options = {});

  /// An ODOMETRY sample (pose and twist), in the order the service would receive it.
  void on_odometry(const OdometrySample& sample);
  /// An LMS100_SCAN: extracted at once with the latest odometry twist, as the service does.
  void on_scan(const LaserScan& scan);

  /// The scans with their odometry pose, in time order (those without odometry dropped).
  std::vector<DriveScan> finish();
  const DriveScanCounts& counts() const { return counts_; }

 private:
  void keep_diffuse(const LaserScan& scan, const std::vector<ReflectorDetection>& detections, DriveScan& out);

  ExtractorNode node_;
  double energy_threshold_8bit_;
  double odometry_max_age_s_;  ///< the extractor's freshness rule for the twist; < 0: no compensation
  Pose2 robot_T_laser_;
  DriveScanOptions options_;
  BodyTwist latest_twist_;
  BeamTable table_;
  std::vector<char> in_detection_;
  std::vector<OdometrySample> odometry_;
  std::vector<DriveScan> scans_;
  DriveScanCounts counts_;
};

}  // namespace refloc
