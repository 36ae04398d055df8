#pragma once
// The two residuals of the survey's batch adjustment as Ceres autodiff functors (only
// drive_bundle_adjustment.cpp includes this). Poses are (x, y, theta) of map_T_robot.

#include "common/se2.hpp"

#include <ceres/ceres.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>

namespace refloc {

/// Upper-triangular U with U^T U = covariance^-1: r = U e is the whitened residual.
template <int N>
Eigen::Matrix<double, N, N> whitening_of(const Eigen::Matrix<double, N, N>& covariance) {
  const Eigen::Matrix<double, N, N> information = covariance.inverse();
  return Eigen::LLT<Eigen::Matrix<double, N, N>>(information).matrixU();
}

/// e = laser_p - laser_T_map map_p - b u: the pose solver's model (range_bias_refinement.hpp)
/// with the landmark free.
struct PointResidual {
  Eigen::Vector2d laser_p;
  Eigen::Vector2d direction;  ///< u, the measured unit direction
  Eigen::Matrix2d whitening;
  Pose2 robot_T_laser;

  template <class T>
  void error(const T* pose, const T* landmark, const T* bias, T* e) const {
    const T c = ceres::cos(pose[2]), s = ceres::sin(pose[2]);
    // map_T_laser = map_T_robot * robot_T_laser
    const T lx = pose[0] + c * robot_T_laser.x - s * robot_T_laser.y;
    const T ly = pose[1] + s * robot_T_laser.x + c * robot_T_laser.y;
    const T lt = pose[2] + robot_T_laser.theta;
    const T cl = ceres::cos(lt), sl = ceres::sin(lt);
    const T dx = landmark[0] - lx, dy = landmark[1] - ly;
    const T px = cl * dx + sl * dy, py = -sl * dx + cl * dy;  // laser_p of the landmark
    e[0] = laser_p.x() - px - bias[0] * direction.x();
    e[1] = laser_p.y() - py - bias[0] * direction.y();
  }

  template <class T>
  bool operator()(const T* pose, const T* landmark, const T* bias, T* residual) const {
    T e[2];
    error(pose, landmark, bias, e);
    residual[0] = whitening(0, 0) * e[0] + whitening(0, 1) * e[1];
    residual[1] = whitening(1, 0) * e[0] + whitening(1, 1) * e[1];
    return true;
  }
};

/// The odometry displacement between two scans: (R_i^T (t_j - t_i), theta_j - theta_i)
/// against odom_i^-1 odom_j, in pose i's body frame.
struct OdometryResidual {
  Pose2 measured;  ///< odom_i^-1 odom_j
  Eigen::Matrix3d whitening;

  template <class T>
  bool operator()(const T* pose_i, const T* pose_j, T* residual) const {
    const T c = ceres::cos(pose_i[2]), s = ceres::sin(pose_i[2]);
    const T dx = pose_j[0] - pose_i[0], dy = pose_j[1] - pose_i[1];
    T e[3];
    e[0] = c * dx + s * dy - measured.x;
    e[1] = -s * dx + c * dy - measured.y;
    const T dtheta = pose_j[2] - pose_i[2] - measured.theta;
    e[2] = ceres::atan2(ceres::sin(dtheta), ceres::cos(dtheta));
    for (int r = 0; r < 3; ++r)
      residual[r] = whitening(r, 0) * e[0] + whitening(r, 1) * e[1] + whitening(r, 2) * e[2];
    return true;
  }
};

}  // namespace refloc
