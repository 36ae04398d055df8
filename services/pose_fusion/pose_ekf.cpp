#include "pose_fusion/pose_ekf.hpp"

#include "common/covariance_propagation.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

namespace refloc {
namespace {

Eigen::Vector3d innovation(const Pose2& x, const Pose2& z) {
  return {z.x - x.x, z.y - x.y, angle_diff(z.theta, x.theta)};
}

}  // namespace

PoseEstimate ekf_predict(const PoseEstimate& prior, const Pose2& delta, const Eigen::Matrix3d& q) {
  return {prior.map_T_robot * delta, compose_covariance(prior.map_T_robot, prior.covariance, delta, q)};
}

double mahalanobis_squared(const PoseEstimate& prior, const Pose2& z, const Eigen::Matrix3d& r) {
  const Eigen::Vector3d y = innovation(prior.map_T_robot, z);
  const Eigen::Matrix3d s = prior.covariance + r;
  return y.dot(s.ldlt().solve(y));
}

PoseEstimate ekf_correct(const PoseEstimate& prior, const Pose2& z, const Eigen::Matrix3d& r) {
  const Eigen::Vector3d y = innovation(prior.map_T_robot, z);
  const Eigen::Matrix3d s = prior.covariance + r;
  const Eigen::Matrix3d k = prior.covariance * s.inverse();
  const Eigen::Vector3d dx = k * y;
  PoseEstimate posterior;
  posterior.map_T_robot = {prior.map_T_robot.x + dx.x(), prior.map_T_robot.y + dx.y(),
                           wrap_angle(prior.map_T_robot.theta + dx.z())};
  const Eigen::Matrix3d i_k = Eigen::Matrix3d::Identity() - k;
  posterior.covariance = i_k * prior.covariance * i_k.transpose() + k * r * k.transpose();
  posterior.covariance = 0.5 * (posterior.covariance + posterior.covariance.transpose());
  return posterior;
}

}  // namespace refloc
