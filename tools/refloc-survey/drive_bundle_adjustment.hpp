#pragma once
// The survey's back end: one batch least-squares (Ceres) over every scan's robot pose, the
// reflector positions and the LMS100's common range bias b. Terms:
//  - each detection of a landmark: the laser-frame point residual of the pose solver
//    (e = laser_p - laser_T_map map_p - b u, u the measured direction), whitened by the
//    extractor's covariance, under a Huber loss (a bad association or a mixed pixel);
//  - each pair of consecutive scans: the odometry displacement between them, whitened by the
//    robot's odometry noise model (common/odometry_noise);
//  - the frame: the first pose held at the start pose, or two or more anchor landmarks held at
//    the coordinates the user gave (then every pose is free).
// Each landmark's 2x2 covariance and b's sigma come from ceres::Covariance at the solution.

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <cmath>

#include <string>
#include <vector>

namespace refloc {

/// One detection of a landmark from one pose.
struct BundleObservation {
  int pose = -1;
  int landmark = -1;
  int detection = -1;  ///< the caller's: which detection of the scan (not used by the solve)
  Eigen::Vector2d laser_p = Eigen::Vector2d::Zero();                ///< measured centre, laser frame [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity() * 1e-4;  ///< the extractor's [m^2]
};

/// A landmark held at a given position: it fixes the map frame.
struct BundleAnchor {
  int landmark = -1;
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< [m]
};

struct BundleProblem {
  std::vector<Pose2> map_T_robot;               ///< initial pose of every scan
  std::vector<Pose2> odom_T_robot;              ///< odometry at every scan (same length)
  std::vector<Eigen::Vector2d> map_p_landmark;  ///< initial landmark positions [m]
  std::vector<BundleObservation> observations;
  std::vector<BundleAnchor> anchors;  ///< empty: the first pose is held instead
  Pose2 robot_T_laser;
  OdometryNoise odometry_noise;
  double angle_increment = 0.0;  ///< the scans' beam step (the coarsest) [rad]
};

struct BundleOptions {
  bool estimate_range_bias = true;     ///< false: b held at 0
  double detection_min_sigma = 0.002;  ///< floor of a detection's std dev, as the pose solver's [m]
  double huber_scale = 3.0;            ///< Huber loss threshold on the whitened residual [-]
  /// Floors of the odometry term's std devs: a robot standing still would pin its poses to
  /// each other with infinite weight [m], [rad].
  double odometry_min_sigma_m = 2e-4;
  double odometry_min_sigma_rad = 2e-4;
  /// Detections of one landmark from nearly the same view share their errors (a robot standing
  /// still sees the reflector between the same beams scan after scan: the across-beam
  /// quantization of a 2-3 beam fit repeats exactly), so each run of views whose predicted
  /// bearing stays within this many of the scans' beam steps of the run's first, and range
  /// within same_view_range_m, weighs as one detection together. 0 = every detection
  /// independent [beam steps].
  double same_view_beam_steps = 0.5;
  double same_view_range_m = 0.05;  ///< see same_view_beam_steps [m]
  int max_iterations = 100;
  int threads = 2;
  bool compute_covariance = true;
};

struct BundleLandmark {
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();       ///< [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();  ///< [m^2]; zero for an anchor
  /// The covariance with the frame's own uncertainty taken out (a rigid motion of the whole map,
  /// from holding the first pose): what localization in the map and a comparison after a rigid
  /// alignment see. Zero when not computed (anchors hold the frame, or too many landmarks) [m^2].
  Eigen::Matrix2d frame_free_covariance = Eigen::Matrix2d::Zero();
  int observations = 0;
  double residual_rms = 0.0;    ///< RMS of |e| over its observations at the solution [m]
  double normalised_rms = 0.0;  ///< RMS of the whitened residual [-]
  int outliers = 0;             ///< observations whose whitened residual exceeds huber_scale
};

struct BundleResult {
  bool ok = false;
  std::string message;  ///< Ceres' brief report, or why not ok
  std::vector<Pose2> map_T_robot;
  std::vector<BundleLandmark> landmarks;
  /// Per observation e = laser_p - predicted at the solution, in the laser frame [m].
  std::vector<Eigen::Vector2d> residuals;
  double range_bias = 0.0;        ///< measured - true range [m]
  double range_bias_sigma = 0.0;  ///< [m]; 0 when held
  double chi2_per_dof = 0.0;      ///< 2 cost / (residuals - parameters), robust loss aside
  int iterations = 0;
  double solve_s = 0.0;       ///< wall time of the solve [s]
  double covariance_s = 0.0;  ///< of the covariance [s]
};

/// Solve problem; the result's landmarks and poses follow the problem's order.
BundleResult adjust_bundle(const BundleProblem& problem, const BundleOptions& options);

}  // namespace refloc
