#pragma once
// Which scans get motion compensation: the latest ODOMETRY twist is used when it is
// fresh enough (by message utime, either side of the scan); otherwise the detections
// stay as measured and the scan is counted as one without fresh odometry.

#include "common/odometry_sample.hpp"
#include "common/reflector_detection.hpp"
#include "common/se2.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace refloc {

enum class CompensationOutcome {
  kOff,              ///< compensation disabled by configuration
  kCompensated,      ///< detections moved to the scan's reference time
  kNoFreshOdometry,  ///< none or too old: detections left as measured
};

class MotionCompensator {
 public:
  /// odometry_max_age [s]: |odometry utime - scan utime| above this is not fresh.
  MotionCompensator(bool enabled, double odometry_max_age, const Pose2& robot_T_laser);

  void on_odometry(const OdometrySample& sample) { last_ = sample; }
  /// Whether the latest odometry may compensate a scan at scan_utime [us].
  bool fresh(int64_t scan_utime) const;
  /// Compensate detections to scan_utime when enabled and fresh.
  CompensationOutcome apply(std::vector<ReflectorDetection>& detections, int64_t scan_utime) const;

 private:
  bool enabled_;
  int64_t max_age_us_;
  Pose2 robot_T_laser_;
  std::optional<OdometrySample> last_;
};

}  // namespace refloc
