#include "reflector_extractor/motion_compensator.hpp"

#include "reflector_extractor/motion_compensation.hpp"

#include <cstdlib>

namespace refloc {

MotionCompensator::MotionCompensator(bool enabled, double odometry_max_age, const Pose2& robot_T_laser)
    : enabled_(enabled),
      max_age_us_(static_cast<int64_t>(odometry_max_age * 1e6)),
      robot_T_laser_(robot_T_laser) {}

bool MotionCompensator::fresh(int64_t scan_utime) const {
  return last_ && std::llabs(last_->utime - scan_utime) <= max_age_us_;
}

CompensationOutcome MotionCompensator::apply(std::vector<ReflectorDetection>& detections,
                                             int64_t scan_utime) const {
  if (!enabled_) return CompensationOutcome::kOff;
  if (!fresh(scan_utime)) return CompensationOutcome::kNoFreshOdometry;
  compensate_motion(detections, scan_utime, last_->twist, robot_T_laser_);
  return CompensationOutcome::kCompensated;
}

}  // namespace refloc
