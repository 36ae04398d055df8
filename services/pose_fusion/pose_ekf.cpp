#include "pose_fusion/pose_ekf.hpp"

#include "common/covariance_propagation.hpp"
#include "common/laser_point_model.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace refloc {
namespace {

using StateVector = Eigen::Matrix<double, kStateDim, 1>;

void add_to_state(FusionState& state, const StateVector& dx) {
  Pose2& p = state.map_T_robot;
  p = {p.x + dx(0), p.y + dx(1), wrap_angle(p.theta + dx(2))};
  state.range_bias_m += dx(StateIndex::kRangeBias);
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) state.odometry_error(r, c) += dx(StateIndex::kOdometryError + 3 * r + c);
  state.scan_time_offset_s += dx(StateIndex::kScanTimeOffset);
}

/// P - K H P with K = P H^T S^-1, kept symmetric. Cheaper than the Joseph form and
/// equal to it for the optimal gain; the symmetrisation keeps rounding from accumulating.
template <int M>
void correct(FusionState& state, const Eigen::Matrix<double, M, 1>& y,
             const Eigen::Matrix<double, M, kStateDim>& h, const Eigen::Matrix<double, M, M>& s) {
  const Eigen::Matrix<double, M, kStateDim> hp = h * state.covariance;
  const Eigen::Matrix<double, kStateDim, M> k = (s.ldlt().solve(hp)).transpose();
  add_to_state(state, k * y);
  state.covariance -= k * hp;
  state.covariance = 0.5 * (state.covariance + state.covariance.transpose()).eval();
}

}  // namespace

void ekf_predict(FusionState& state, const Pose2& measured_delta, const Eigen::Matrix3d& q, double dt_s,
                 const StateRandomWalk& walk) {
  const Eigen::Vector3d d(measured_delta.x, measured_delta.y, measured_delta.theta);
  const Eigen::Vector3d corrected = d + state.odometry_error * d;
  const Pose2 delta{corrected.x(), corrected.y(), corrected.z()};
  // F is the identity but for its first three rows: P' = F P F^T touches only the pose rows
  // and columns (a quarter of the dense product's work).
  Eigen::Matrix<double, 3, kStateDim> f_top = Eigen::Matrix<double, 3, kStateDim>::Zero();
  f_top.leftCols<3>() = compose_jacobian_lhs(state.map_T_robot, delta);
  const Eigen::Matrix3d g = compose_jacobian_rhs(state.map_T_robot);
  // d(E d)/dE for E row-major: row r of E multiplies d.
  for (int r = 0; r < 3; ++r)
    f_top.block<3, 3>(0, StateIndex::kOdometryError + 3 * r) = g.col(r) * d.transpose();
  state.map_T_robot = state.map_T_robot * delta;
  StateCovariance& p = state.covariance;
  const Eigen::Matrix<double, 3, kStateDim> fp = f_top * p;  // rows 0-2 of F P
  const Eigen::Matrix3d fpf = fp * f_top.transpose();        // block (0-2, 0-2) of F P F^T
  p.topRows<3>() = fp;
  p.leftCols<3>() = fp.transpose();
  p.topLeftCorner<3, 3>() = fpf;
  p.topLeftCorner<3, 3>() += g * q * g.transpose();
  p(StateIndex::kRangeBias, StateIndex::kRangeBias) +=
      walk.range_bias_m_per_sqrt_s * walk.range_bias_m_per_sqrt_s * std::max(dt_s, 0.0);
  const double motion = std::hypot(d.x(), d.y()) + std::abs(d.z());
  const double e_var = walk.odometry_error_per_sqrt_m * walk.odometry_error_per_sqrt_m * motion;
  for (int i = 0; i < 9; ++i) p(StateIndex::kOdometryError + i, StateIndex::kOdometryError + i) += e_var;
  p(StateIndex::kScanTimeOffset, StateIndex::kScanTimeOffset) +=
      walk.scan_time_offset_s_per_sqrt_s * walk.scan_time_offset_s_per_sqrt_s * std::max(dt_s, 0.0);
}

double pose_mahalanobis_squared(const FusionState& state, const Pose2& z, const Eigen::Matrix3d& r) {
  const Pose2& x = state.map_T_robot;
  const Eigen::Vector3d y(z.x - x.x, z.y - x.y, angle_diff(z.theta, x.theta));
  const Eigen::Matrix3d s = state.covariance.topLeftCorner<3, 3>() + r;
  return y.dot(s.ldlt().solve(y));
}

void ekf_correct_pose(FusionState& state, const Pose2& z, const Eigen::Matrix3d& r) {
  const Pose2& x = state.map_T_robot;
  const Eigen::Vector3d y(z.x - x.x, z.y - x.y, angle_diff(z.theta, x.theta));
  Eigen::Matrix<double, 3, kStateDim> h = Eigen::Matrix<double, 3, kStateDim>::Zero();
  h.leftCols<3>().setIdentity();
  const Eigen::Matrix3d s = state.covariance.topLeftCorner<3, 3>() + r;
  correct<3>(state, y, h, s);
}

DetectionInnovation detection_innovation(const FusionState& state, const MatchedDetection& detection,
                                         const Pose2& robot_T_laser, double map_variance,
                                         const ScanTiming& timing) {
  Eigen::Vector2d residual_no_bias;
  Eigen::Matrix<double, 2, 3> d_residual_d_pose;
  laser_point_residual_and_jacobian(detection.map_point, detection.laser_point, state.map_T_robot,
                                    robot_T_laser, residual_no_bias, d_residual_d_pose);
  const double measured_range = detection.laser_point.norm();
  const Eigen::Vector2d u = measured_range > 0.0 ? Eigen::Vector2d(detection.laser_point / measured_range)
                                                 : Eigen::Vector2d::Zero();
  DetectionInnovation out;
  // The measured point is where the map point was tau after the stamp: z = h(x) + b u + tau g.
  const Eigen::Vector2d g = laser_point_rate(detection.laser_point, timing);
  out.y = residual_no_bias - state.range_bias_m * u - state.scan_time_offset_s * g;
  out.h.leftCols<3>() = -d_residual_d_pose;
  out.h.col(StateIndex::kRangeBias) = u;
  out.h.col(StateIndex::kScanTimeOffset) = g;
  out.r = detection.covariance + map_variance * Eigen::Matrix2d::Identity();
  out.s = out.h * state.covariance * out.h.transpose() + out.r;
  const Eigen::LDLT<Eigen::Matrix2d> ldlt(out.s);
  out.mahalanobis_squared = ldlt.info() == Eigen::Success && ldlt.isPositive()
                                ? out.y.dot(ldlt.solve(out.y))
                                : std::numeric_limits<double>::quiet_NaN();
  return out;
}

void ekf_correct_detection(FusionState& state, const DetectionInnovation& innovation) {
  correct<2>(state, innovation.y, innovation.h, innovation.s);
}

Eigen::Vector2d laser_point_rate(const Eigen::Vector2d& laser_point, const ScanTiming& timing) {
  // z = R^T (m - p): dz/dt = -w J z - v, J the +90 deg rotation.
  return -timing.yaw_rate * Eigen::Vector2d(-laser_point.y(), laser_point.x()) - timing.laser_velocity;
}

void ekf_correct_scan(FusionState& state, const std::vector<MatchedDetection>& detections,
                      const Pose2& robot_T_laser, double map_variance, const ScanTiming& timing) {
  for (const MatchedDetection& d : detections)
    ekf_correct_detection(state, detection_innovation(state, d, robot_T_laser, map_variance, timing));
}

}  // namespace refloc
