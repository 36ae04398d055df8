#include "reflector_extractor/motion_compensator.hpp"

#include "reflector_extractor/motion_compensation.hpp"

#include <fmt/format.h>

#include <cstdlib>

namespace refloc {

const char* to_string(CompensationOutcome outcome) {
  switch (outcome) {
    case CompensationOutcome::kOff:
      return "off";
    case CompensationOutcome::kOdometry:
      return "odometry";
    case CompensationOutcome::kFixes:
      return "fixes";
    case CompensationOutcome::kNoMotionSource:
      return "none";
  }
  return "?";
}

MotionCompensator::MotionCompensator(bool enabled, double odometry_max_age, const Pose2& robot_T_laser,
                                     const FixVelocityConfig& fix_velocity)
    : enabled_(enabled),
      max_age_us_(static_cast<int64_t>(odometry_max_age * 1e6)),
      robot_T_laser_(robot_T_laser),
      fixes_enabled_(fix_velocity.enabled),
      fix_velocity_(fix_velocity) {}

bool MotionCompensator::fresh(int64_t scan_utime) const {
  return last_ && std::llabs(last_->utime - scan_utime) <= max_age_us_;
}

CompensationOutcome MotionCompensator::apply(std::vector<ReflectorDetection>& detections,
                                             int64_t scan_utime) const {
  if (!enabled_) return CompensationOutcome::kOff;
  if (fresh(scan_utime)) {
    compensate_motion(detections, scan_utime, last_->twist, robot_T_laser_);
    return CompensationOutcome::kOdometry;
  }
  if (!fixes_enabled_) return CompensationOutcome::kNoMotionSource;
  const FixVelocityEstimate estimate = fix_velocity_.estimate(scan_utime);
  if (!estimate.ok()) return CompensationOutcome::kNoMotionSource;
  compensate_motion(detections, scan_utime, estimate.twist, robot_T_laser_);
  return CompensationOutcome::kFixes;
}

std::string MotionCompensator::describe(CompensationOutcome outcome, int64_t scan_utime) const {
  if (outcome == CompensationOutcome::kOff) return "motion compensation off";
  if (outcome == CompensationOutcome::kOdometry) return "motion compensation from ODOMETRY";
  const std::string odometry = last_ ? fmt::format("ODOMETRY {:.2f} s from the scan",
                                                   static_cast<double>(scan_utime - last_->utime) * 1e-6)
                                     : "no ODOMETRY";
  const FixVelocityEstimate e = fix_velocity_.estimate(scan_utime);
  if (outcome == CompensationOutcome::kFixes) {
    return fmt::format(
        "motion compensation from LASER_POSE fixes ({}; {} fixes, twist {:.3f} m/s {:.3f} m/s {:.3f} rad/s)",
        odometry, e.fixes, e.twist.vx, e.twist.vy, e.twist.wz);
  }
  const std::string fixes = !fixes_enabled_ ? "fixes not used (fix_velocity/enabled false)"
                                            : fmt::format("fixes: {} ({} in the window, newest {:.2f} s old)",
                                                          to_string(e.status), e.fixes, e.newest_age_s);
  return fmt::format("no motion compensation: {}, {}", odometry, fixes);
}

}  // namespace refloc
