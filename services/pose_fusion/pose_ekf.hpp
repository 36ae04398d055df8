#pragma once
// The two EKF steps over map_T_robot = (x, y, theta): predict with a body-frame
// odometry displacement, correct with an absolute pose measurement. The
// measurement model is the identity, with the heading innovation wrapped.

#include "common/se2.hpp"

#include <Eigen/Core>

namespace refloc {

struct PoseEstimate {
  Pose2 map_T_robot;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  ///< [m^2, m rad, rad^2]
};

/// x' = x * delta; P' = F P F^T + G q G^T with q the covariance of delta (body frame).
PoseEstimate ekf_predict(const PoseEstimate& prior, const Pose2& delta, const Eigen::Matrix3d& q);

/// Squared Mahalanobis distance of a measured pose z (covariance r) from the prior.
double mahalanobis_squared(const PoseEstimate& prior, const Pose2& z, const Eigen::Matrix3d& r);

/// Kalman update with a pose measurement z of covariance r (Joseph form, stays symmetric).
PoseEstimate ekf_correct(const PoseEstimate& prior, const Pose2& z, const Eigen::Matrix3d& r);

}  // namespace refloc
