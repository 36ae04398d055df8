#pragma once
// The EKF steps over the fusion state: map_T_robot = (x, y, theta), the laser's common
// range bias b (measured - true range, the LMS100's +-30 mm) and the odometry's
// calibration error E (3x3: the true body increment is (I + E) times the measured one,
// (dx, dy, dtheta)). E is what 1 % worn rollers or a wheel radius a little off make of
// odometry: a drift proportional to the motion, which the filter learns from the laser
// instead of covering it with a large random process noise (services/pose_fusion/README.md).
//
// The fourteenth state is the scans' time offset tau = true measurement time - stamp: a link
// delay no clock fit can see (a real LMS100's Ethernet, ~0.4 ms) or a stamping error. It moves
// every detection along the laser's motion (tau times the point's rate), so it shows only while
// the robot moves and turns, and until it is known the pose's covariance carries it.
//
// Measurements: an absolute pose (a LASER_POSE fix; identity model, heading innovation
// wrapped), or one matched reflector detection: the laser-frame centre z of map reflector
// m is z = laser_T_map * m + b * u, u the measured direction, with the detection's 2x2
// covariance plus the map's.

#include "common/se2.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

constexpr int kStateDim = 14;
using StateCovariance = Eigen::Matrix<double, kStateDim, kStateDim>;
/// Where each part of the state sits in StateCovariance.
struct StateIndex {
  static constexpr int kPose = 0;             ///< x, y, theta
  static constexpr int kRangeBias = 3;        ///< b
  static constexpr int kOdometryError = 4;    ///< E, row-major (E00 E01 E02 E10 ... E22)
  static constexpr int kScanTimeOffset = 13;  ///< tau
};

/// The pose with the 3x3 block of its covariance.
struct PoseEstimate {
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2, m rad, rad^2]
};

struct FusionState {
  Pose2 map_T_robot;
  double range_bias_m = 0.0;                                 ///< b = measured - true range [m]
  Eigen::Matrix3d odometry_error = Eigen::Matrix3d::Zero();  ///< E: true increment = (I + E) measured
  double scan_time_offset_s = 0.0;                           ///< tau = true scan time - stamp [s]
  StateCovariance covariance = StateCovariance::Zero();      ///< [m, rad, m, 1, s] units per state

  PoseEstimate pose() const { return {map_T_robot, covariance.topLeftCorner<3, 3>()}; }
};

/// Random walks of the states other than the pose. Zero: the state only changes by measurements.
struct StateRandomWalk {
  double range_bias_m_per_sqrt_s = 0.0;
  /// Per sqrt of motion, a radian turned counting as a metre driven [1/sqrt(m)].
  double odometry_error_per_sqrt_m = 0.0;
  double scan_time_offset_s_per_sqrt_s = 0.0;
};

/// x' = x * ((I + E) delta); q the covariance of the random part of delta (body frame);
/// dt_s the step's duration for b's random walk.
void ekf_predict(FusionState& state, const Pose2& measured_delta, const Eigen::Matrix3d& q, double dt_s,
                 const StateRandomWalk& walk);

/// Squared Mahalanobis distance of a measured pose z (covariance r) from the state's pose.
double pose_mahalanobis_squared(const FusionState& state, const Pose2& z, const Eigen::Matrix3d& r);
/// Kalman update with a pose measurement z of covariance r.
void ekf_correct_pose(FusionState& state, const Pose2& z, const Eigen::Matrix3d& r);

/// One detection associated with one map reflector.
struct MatchedDetection {
  Eigen::Vector2d laser_point = Eigen::Vector2d::Zero();     ///< measured centre, laser frame [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity();  ///< of laser_point [m^2]
  Eigen::Vector2d map_point = Eigen::Vector2d::Zero();       ///< the map reflector's centre [m]
  int map_id = 0;
};

/// A detection's innovation against a state, with what the update needs.
struct DetectionInnovation {
  Eigen::Vector2d y = Eigen::Vector2d::Zero();  ///< measured - predicted [m]
  Eigen::Matrix<double, 2, kStateDim> h = Eigen::Matrix<double, 2, kStateDim>::Zero();
  Eigen::Matrix2d s = Eigen::Matrix2d::Identity();  ///< H P H^T + R [m^2]
  Eigen::Matrix2d r = Eigen::Matrix2d::Identity();  ///< detection + map covariance [m^2]
  double mahalanobis_squared = 0.0;                 ///< y^T S^-1 y; NaN when S is singular
};

/// The laser's twist at a scan, in its own frame: what turns the time offset into metres.
struct ScanTiming {
  Eigen::Vector2d laser_velocity = Eigen::Vector2d::Zero();  ///< [m/s]
  double yaw_rate = 0.0;                                     ///< [rad/s]
};

/// d(laser-frame point)/dt: a fixed point seen from a moving laser.
Eigen::Vector2d laser_point_rate(const Eigen::Vector2d& laser_point, const ScanTiming& timing);

/// robot_T_laser: the laser mount; map_variance: the map position's variance per axis [m^2].
DetectionInnovation detection_innovation(const FusionState& state, const MatchedDetection& detection,
                                         const Pose2& robot_T_laser, double map_variance,
                                         const ScanTiming& timing = {});
/// Kalman update with one detection's innovation (computed on this state).
void ekf_correct_detection(FusionState& state, const DetectionInnovation& innovation);
/// One detection after the other, each innovation computed on the state the previous one left.
void ekf_correct_scan(FusionState& state, const std::vector<MatchedDetection>& detections,
                      const Pose2& robot_T_laser, double map_variance, const ScanTiming& timing);

}  // namespace refloc
