#pragma once
// Motion compensation without odometry: the robot's body twist fitted to its own recent
// laser fixes (LASER_POSE with status OK, map_T_robot at each scan's first beam). A scan
// is ~15 ms long and the fixes come every 20 ms, so a straight-line fit of x, y and the
// unwrapped heading over the last few hundred milliseconds gives the velocity to well
// under the scan's own smear (README: "Motion compensation without odometry").

#include "common/body_twist.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

/// One LASER_POSE as the extractor reads it (plain form of pose2d_t).
struct LaserPoseFix {
  int64_t utime = 0;  ///< the fix's scan time (first beam) [us]
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2, m rad, rad^2]
  bool ok = false;                                       ///< status OK (only those are used)
};

/// deploy/config/reflector_extractor.json "fix_velocity".
struct FixVelocityConfig {
  bool enabled = true;  ///< use LASER_POSE fixes when ODOMETRY is absent or stale
  /// Fixes older than this before the newest are dropped [s]; longer: less noise, more lag
  /// behind an acceleration (README numbers).
  double window_s = 0.3;
  /// The newest fix further than this from the scan (either side) is too old to say how
  /// the robot moves now [s].
  double max_age_s = 0.2;
  int min_fixes = 5;                 ///< fewer fixes in the window: no estimate
  double min_span_s = 0.08;          ///< oldest to newest fix in the window at least this [s]
  double max_rms_residual_m = 0.03;  ///< fixes scattered more about the line: no estimate [m]
};

/// Why there is no estimate (or kOk).
enum class FixVelocityStatus { kOk, kNoFixes, kStale, kTooFew, kScattered, kImplausible };
const char* to_string(FixVelocityStatus status);

struct FixVelocityEstimate {
  FixVelocityStatus status = FixVelocityStatus::kNoFixes;
  BodyTwist twist;            ///< body frame [m/s, m/s, rad/s]; only with kOk
  int fixes = 0;              ///< fixes in the window
  double rms_residual = 0.0;  ///< of the position fit [m]
  double newest_age_s = 0.0;  ///< scan time - newest fix time [s]
  bool ok() const { return status == FixVelocityStatus::kOk; }
};

/// Keeps the OK fixes of the last window_s; fits a constant body twist on demand.
/// Fixes are expected judged (finite, plausible, stamps increasing: ExtractorNode does it).
class FixVelocityEstimator {
 public:
  explicit FixVelocityEstimator(const FixVelocityConfig& config = {});

  /// Adds an OK fix (others are ignored). A fix not newer than the newest is ignored; one
  /// that implies a speed beyond TwistBounds from the newest (a relocalization jump)
  /// starts the window over.
  void add(const LaserPoseFix& fix);
  /// The twist for a scan at scan_utime [us]: slopes of x, y and the unwrapped heading
  /// over time, turned into the body frame at the heading of the window's mean time.
  FixVelocityEstimate estimate(int64_t scan_utime) const;

  int fixes() const { return static_cast<int>(fixes_.size()); }

 private:
  FixVelocityConfig config_;
  int64_t window_us_;
  int64_t max_age_us_;
  std::vector<LaserPoseFix> fixes_;  ///< oldest first, within window_s of the newest
};

}  // namespace refloc
