#pragma once
// The pose with a common range offset b (measured - true range of every detection): the
// residual of detection i is e_i = laser_p_i - h_i(map_T_robot) - b u_i, u_i its measured
// direction (b moves a detection along its beam; the bearing noise makes the difference between
// the measured and the predicted direction ~0.1 mm at b = 30 mm). The state is (x, y, theta, b);
// b gets a Gaussian prior. Where b is estimated, the pose covariance is the marginal of the
// joint one; where it is not, b's prior sigma is pushed through dpose/db into the covariance:
// either way an unknown offset is not reported as certainty.

#include "pose_solver/point_observation.hpp"

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

/// What b is believed to be before this scan's data.
struct RangeBiasPrior {
  double mean = 0.0;     ///< [m]
  double sigma = 0.03;   ///< [m]; 0: known exactly
  bool estimate = true;  ///< false: b is held at mean and only inflates the covariance
};

struct BiasedPoseResult {
  bool converged = false;
  Pose2 map_T_robot;
  double range_bias = 0.0;  ///< [m] the prior mean when not estimated
  /// J^T W J of the observations alone over (x, y, theta, b) at the solution (no prior).
  Eigen::Matrix4d data_information = Eigen::Matrix4d::Zero();
  double cost = 0.0;  ///< sum of e^T W e (+ the prior's term when b is estimated)
  int iterations = 0;
};

/// Levenberg-Marquardt on (x, y, theta) and, when prior.estimate with prior.sigma > 0, b; else b =
/// prior.mean. Observations with use[i] != 0 (all if use is null).
BiasedPoseResult refine_pose_and_range_bias(const std::vector<PointObservation>& observations,
                                            const std::vector<char>* use, const Pose2& robot_T_laser,
                                            const Pose2& initial_map_T_robot, const RangeBiasPrior& prior,
                                            int max_iterations, double convergence_step);

/// The sigma of b from a scan's data alone with the pose free (1 / sqrt of the Schur complement
/// of the pose block) [m]: the geometric test of whether a scan can tell b from a translation.
/// Infinite when it cannot at all (a singular pose block, or no b information left).
double range_bias_scan_sigma(const Eigen::Matrix4d& data_information);

/// Pose covariance with b estimated: the (x, y, theta) block of (data_information + prior)^-1;
/// bias_sigma gets b's posterior sigma [m]. False when not invertible.
bool pose_covariance_bias_estimated(const Eigen::Matrix4d& data_information, double prior_sigma,
                                    Eigen::Matrix3d& covariance, double& bias_sigma);

/// Pose covariance with b held fixed at a value uncertain by bias_sigma [m]:
/// H_pp^-1 + J_b bias_sigma^2 J_b^T with J_b = dpose/db = -H_pp^-1 H_pb. False when singular.
bool pose_covariance_bias_fixed(const Eigen::Matrix4d& data_information, double bias_sigma,
                                Eigen::Matrix3d& covariance);

/// out = in with b taken off each range (laser_p moved by -b along its direction).
void remove_range_bias(const std::vector<PointObservation>& in, double bias,
                       std::vector<PointObservation>& out);

}  // namespace refloc
