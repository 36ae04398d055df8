#include "reflector_extractor/motion_compensation.hpp"

#include <cmath>

namespace refloc {

Pose2 laser_motion(const BodyTwist& robot_twist, const Pose2& robot_T_laser, double dt) {
  return robot_T_laser.inverse() * se2_exp(robot_twist, dt) * robot_T_laser;
}

void compensate_motion(std::vector<ReflectorDetection>& detections, int64_t reference_utime,
                       const BodyTwist& robot_twist, const Pose2& robot_T_laser) {
  for (ReflectorDetection& d : detections) {
    const double dt = static_cast<double>(d.utime - reference_utime) * 1e-6;
    const Pose2 reference_T_beam = laser_motion(robot_twist, robot_T_laser, dt);
    const Eigen::Matrix2d rotation = reference_T_beam.rotation();
    d.laser_p_center = reference_T_beam * d.laser_p_center;
    d.covariance = rotation * d.covariance * rotation.transpose();
    d.range = d.laser_p_center.norm();
    d.bearing = std::atan2(d.laser_p_center.y(), d.laser_p_center.x());
  }
}

}  // namespace refloc
