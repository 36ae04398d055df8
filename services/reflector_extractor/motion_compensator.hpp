#pragma once
// Which motion moves a scan's detections to its reference time: the latest ODOMETRY twist
// when it is fresh enough (by message utime, either side of the scan); else, without
// odometry (service down, a robot without encoders), the twist fitted to the robot's own
// recent LASER_POSE fixes (fix_velocity_estimator); else none, the detections stay as
// measured. Odometry first: it is measured at 100 Hz, the fixes' twist lags by half its window.

#include "common/odometry_sample.hpp"
#include "common/reflector_detection.hpp"
#include "common/se2.hpp"
#include "reflector_extractor/fix_velocity_estimator.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace refloc {

enum class CompensationOutcome {
  kOff,             ///< compensation disabled by configuration
  kOdometry,        ///< moved with the fresh ODOMETRY twist
  kFixes,           ///< no fresh ODOMETRY: moved with the twist of recent LASER_POSE fixes
  kNoMotionSource,  ///< neither: detections left as measured
};
/// "odometry", "fixes", "none" (or "off").
const char* to_string(CompensationOutcome outcome);

class MotionCompensator {
 public:
  /// odometry_max_age [s]: |odometry utime - scan utime| above this is not fresh.
  MotionCompensator(bool enabled, double odometry_max_age, const Pose2& robot_T_laser,
                    const FixVelocityConfig& fix_velocity = FixVelocityConfig{});

  void on_odometry(const OdometrySample& sample) { last_ = sample; }
  /// A judged LASER_POSE (ExtractorNode checks it); only OK fixes are kept.
  void on_laser_pose(const LaserPoseFix& fix) { fix_velocity_.add(fix); }
  /// Whether the latest odometry may compensate a scan at scan_utime [us].
  bool fresh(int64_t scan_utime) const;
  /// Compensate detections to scan_utime with the first source that is usable.
  CompensationOutcome apply(std::vector<ReflectorDetection>& detections, int64_t scan_utime) const;
  /// Why the scan at scan_utime [us] got outcome, for a log line when the source changes.
  std::string describe(CompensationOutcome outcome, int64_t scan_utime) const;

  const FixVelocityEstimator& fix_velocity() const { return fix_velocity_; }

 private:
  bool enabled_;
  int64_t max_age_us_;
  Pose2 robot_T_laser_;
  bool fixes_enabled_;
  FixVelocityEstimator fix_velocity_;
  std::optional<OdometrySample> last_;
};

}  // namespace refloc
