#pragma once
// One ODOMETRY message (odometry_t) as the libraries read it: pose_fusion steps
// the filter with its pose and distance, the extractor's motion compensation uses
// its twist. Field order keeps {utime, twist} aggregate initialisation valid.

#include "common/body_twist.hpp"
#include "common/se2.hpp"

#include <cstdint>

namespace refloc {

struct OdometrySample {
  int64_t utime = 0;      ///< time of the encoder sample [us]
  BodyTwist twist;        ///< body twist over the last interval [m/s, m/s, rad/s]
  Pose2 odom_T_robot;     ///< pose in the odometry frame [m, m, rad]
  double distance = 0.0;  ///< path length since the odometry service started [m]
};

}  // namespace refloc
