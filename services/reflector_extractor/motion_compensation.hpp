#pragma once
// Motion compensation: the LMS100 sweeps 270 deg in ~15 ms, during which the robot
// moves. Each detection is measured at its own beam time; this moves its centre into the
// laser frame at the scan's reference time (first beam) with exact SE(2) motion under a
// constant body twist (se2_exp).

#include "common/reflector_detection.hpp"
#include "common/se2.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

/// laser_then_T_laser_now after dt [s] for a laser mounted at robot_T_laser on a robot
/// with body twist robot_twist.
Pose2 laser_motion(const BodyTwist& robot_twist, const Pose2& robot_T_laser, double dt);

/// Re-express every detection (centre and covariance) measured at its utime in the laser
/// frame at reference_utime [us]. range and bearing follow the centre; utime is kept.
void compensate_motion(std::vector<ReflectorDetection>& detections, int64_t reference_utime,
                       const BodyTwist& robot_twist, const Pose2& robot_T_laser = Pose2{});

}  // namespace refloc
