#pragma once
// How the laser fixes of a simulated drive err against the simulator's true poses: the numbers
// that say whether the fixes or the odometry model limit a calibration. Per-axis error spread,
// the lag-1 correlation of consecutive fixes' errors, and a similarity fit
//   fix - truth = t + e (p - c) + w J (p - c)     (p the true position, c their centroid)
// whose expansion e is a scale error of the fixes over the drive's area: it enters the wheel
// radius scale one to one when the legs span that area.

#include "calibration_pairs.hpp"

#include <vector>

namespace refloc {

struct FixTruthReport {
  size_t fixes = 0;                       ///< fixes with a true pose around their stamp
  double mean_x_m = 0.0, mean_y_m = 0.0;  ///< mean position error [m]
  double sigma_x_m = 0.0, sigma_y_m = 0.0;
  double sigma_theta_rad = 0.0;
  double lag1_correlation = 0.0;                        ///< of consecutive fixes' position errors [-]
  double expansion = 0.0;                               ///< e of the similarity fit [-] (1e-4 = 0.01 %)
  double rotation_rad = 0.0;                            ///< w of the similarity fit [rad]
  double half_extent_x_m = 0.0, half_extent_y_m = 0.0;  ///< largest |p - c| per axis [m]
};

/// fixes: map_T_robot as LASER_POSE gives them (with configured_robot_T_laser); truth:
/// the true map_T_robot series (GROUND_TRUTH) of a robot whose mount is true_robot_T_laser.
FixTruthReport compare_fixes_with_truth(const std::vector<TimedPose>& fixes,
                                        const std::vector<TimedPose>& truth,
                                        const Pose2& configured_robot_T_laser,
                                        const Pose2& true_robot_T_laser);

}  // namespace refloc
