#pragma once
// What the extractor accepts from the bus. The driver refuses implausible scans, but any
// peer can publish LMS100_SCAN or ODOMETRY, so the extractor judges every number it reads
// against the bounds below and skips (and counts) a message that fails, as a whole: one
// NaN beam means the publisher is broken, and a partly used scan would be silently wrong.

#include "common/input_stream_checks.hpp"
#include "common/laser_scan.hpp"
#include "common/odometry_sample.hpp"
#include "reflector_extractor/fix_velocity_estimator.hpp"

namespace refloc {

/// The bounds of a usable scan.
struct ScanBounds {
  static constexpr size_t kMaxBeams = 4096;         ///< laser_scan_t's maximum (LMS100: 1081)
  static constexpr double kMaxRange_m = 200.0;      ///< beyond any LMS1xx code (16-bit mm x scale 2)
  static constexpr double kMaxScanPeriod_s = 1.0;   ///< the LMS100 scans at 25 or 50 Hz
  static constexpr double kMaxAbsStartAngle = 6.3;  ///< [rad], one turn either way
};

/// A scan is usable when: every angle, time and range is finite; it has 1..kMaxBeams beams;
/// its beams span at most one turn ((n - 1) |angle_increment| <= 2 pi, increment non-zero);
/// 0 < scan_period <= kMaxScanPeriod_s; 0 <= time_increment and n time_increment <=
/// scan_period (the beams of one scan are measured within one period); 0 <= range_min <
/// range_max <= kMaxRange_m; every range in [0, kMaxRange_m]; RSSI either absent or one per
/// beam, rssi_bits 8 or 16 with it (0, 8 or 16 without), each value in [0, 2^bits - 1].
InputFault check_scan(const LaserScan& scan);

/// The bounds of an ODOMETRY twist motion compensation may use: far beyond any indoor
/// Mecanum robot (robot.json's 20 rad/s wheels give about 1 m/s), far below values whose
/// arc over a scan would lose precision.
struct TwistBounds {
  static constexpr double kMaxSpeed_mps = 5.0;      ///< |vx|, |vy|
  static constexpr double kMaxYawRate_radps = 6.3;  ///< |wz|, one turn a second
};

/// The twist is finite and within TwistBounds (the only part of ODOMETRY the extractor reads).
InputFault check_odometry_twist(const OdometrySample& sample);

/// The bounds of a LASER_POSE fix the motion compensation may fit a twist to.
struct LaserPoseBounds {
  static constexpr double kMaxAbsCoordinate_m = 1e4;  ///< no site is 10 km across
  static constexpr double kMaxAbsTheta = 6.3;         ///< [rad]; LASER_POSE is wrapped to (-pi, pi]
  static constexpr double kMaxVariance = 1e6;         ///< [m^2, rad^2]: the solver's "no information"
};

/// x, y, theta finite ("nonfinite") and within LaserPoseBounds ("out_of_bounds"); the
/// covariance symmetric, positive semi-definite, no variance above kMaxVariance
/// ("covariance"). Only OK fixes are judged (the others are not used).
InputFault check_laser_pose(const LaserPoseFix& fix);

}  // namespace refloc
