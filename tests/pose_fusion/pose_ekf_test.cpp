#include "pose_fusion/pose_ekf.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// A state whose range bias and odometry error are known exactly (zero variance).
FusionState pose_only(const Pose2& pose, const Eigen::Matrix3d& covariance) {
  FusionState s;
  s.map_T_robot = pose;
  s.covariance.topLeftCorner<3, 3>() = covariance;
  return s;
}

TEST(PoseEkf, EqualCovariancesAverageTheMeans) {
  FusionState s = pose_only({1.0, 2.0, 0.1}, Eigen::Matrix3d::Identity() * 1e-2);
  ekf_correct_pose(s, {1.2, 1.8, 0.3}, Eigen::Matrix3d::Identity() * 1e-2);
  EXPECT_NEAR(s.map_T_robot.x, 1.1, 1e-12);
  EXPECT_NEAR(s.map_T_robot.y, 1.9, 1e-12);
  EXPECT_NEAR(s.map_T_robot.theta, 0.2, 1e-12);
  EXPECT_NEAR(s.covariance(0, 0), 5e-3, 1e-12);
}

TEST(PoseEkf, HeadingInnovationIsWrapped) {
  const FusionState prior = pose_only({0.0, 0.0, M_PI - 0.05}, Eigen::Matrix3d::Identity() * 1e-2);
  FusionState s = prior;
  ekf_correct_pose(s, {0.0, 0.0, -M_PI + 0.05}, Eigen::Matrix3d::Identity() * 1e-2);
  EXPECT_NEAR(std::abs(s.map_T_robot.theta), M_PI, 1e-12);
  EXPECT_NEAR(pose_mahalanobis_squared(prior, {0.0, 0.0, -M_PI + 0.05}, Eigen::Matrix3d::Identity() * 1e-2),
              0.1 * 0.1 / 2e-2, 1e-12);
}

TEST(PoseEkf, PredictRotatesTheBodyDisplacementIntoTheMap) {
  FusionState s = pose_only({1.0, 1.0, M_PI / 2.0}, Eigen::Matrix3d::Zero());
  const Eigen::Matrix3d q = Eigen::Vector3d(1e-4, 4e-4, 0.0).asDiagonal();
  ekf_predict(s, {0.1, 0.0, 0.0}, q, 0.01, {});
  EXPECT_NEAR(s.map_T_robot.x, 1.0, 1e-12);
  EXPECT_NEAR(s.map_T_robot.y, 1.1, 1e-12);
  EXPECT_NEAR(s.covariance(0, 0), 4e-4, 1e-12);  // body y is map -x now
  EXPECT_NEAR(s.covariance(1, 1), 1e-4, 1e-12);
}

TEST(PoseEkf, PredictAppliesTheOdometryErrorAndItsUncertainty) {
  FusionState s = pose_only({0.0, 0.0, 0.0}, Eigen::Matrix3d::Zero());
  s.odometry_error(0, 0) = 0.01;  // odometry reads 1 % short
  s.covariance(StateIndex::kOdometryError, StateIndex::kOdometryError) = 1e-4;
  ekf_predict(s, {1.0, 0.0, 0.0}, Eigen::Matrix3d::Zero(), 1.0, {});
  EXPECT_NEAR(s.map_T_robot.x, 1.01, 1e-12);
  EXPECT_NEAR(s.covariance(0, 0), 1e-4, 1e-12);  // (1 m x 1 % sigma)^2
  EXPECT_NEAR(s.covariance(0, StateIndex::kOdometryError), 1e-4, 1e-12);
}

/// The laser 0.3 m ahead of the robot centre, robot at (2, 1) facing +y; a reflector at (2, 5)
/// is 3.7 m straight ahead of the laser.
struct DetectionFixture : ::testing::Test {
  Pose2 mount{0.3, 0.0, 0.0};
  FusionState state = pose_only({2.0, 1.0, M_PI / 2.0}, Eigen::Matrix3d::Identity() * 1e-4);
  MatchedDetection detection{{3.7, 0.0}, Eigen::Matrix2d::Identity() * 1e-6, {2.0, 5.0}, 7};
};

TEST_F(DetectionFixture, ExactDetectionHasNoInnovation) {
  const DetectionInnovation in = detection_innovation(state, detection, mount, 0.0);
  EXPECT_NEAR(in.y.norm(), 0.0, 1e-12);
  EXPECT_NEAR(in.mahalanobis_squared, 0.0, 1e-12);
}

TEST_F(DetectionFixture, JacobianMatchesFiniteDifferences) {
  state.range_bias_m = 0.01;
  const DetectionInnovation in = detection_innovation(state, detection, mount, 0.0);
  for (int i = 0; i < 4; ++i) {
    FusionState moved = state;
    const double eps = 1e-7;
    if (i == 0) moved.map_T_robot.x += eps;
    if (i == 1) moved.map_T_robot.y += eps;
    if (i == 2) moved.map_T_robot.theta += eps;
    if (i == 3) moved.range_bias_m += eps;
    // y = z - h: dh/dx = -(dy/dx)
    const Eigen::Vector2d numeric = -(detection_innovation(moved, detection, mount, 0.0).y - in.y) / eps;
    EXPECT_NEAR((numeric - in.h.col(i)).norm(), 0.0, 1e-6) << "state " << i;
  }
}

TEST_F(DetectionFixture, RangeBiasIsLearnedFromALongReading) {
  state.covariance(StateIndex::kRangeBias, StateIndex::kRangeBias) = 0.03 * 0.03;
  state.covariance.topLeftCorner<3, 3>().setZero();  // pose known exactly: all of the error is b
  detection.laser_point = {3.72, 0.0};
  ekf_correct_detection(state, detection_innovation(state, detection, mount, 0.0));
  EXPECT_NEAR(state.range_bias_m, 0.02, 1e-4);
}

TEST_F(DetectionFixture, MapSigmaWidensTheInnovation) {
  detection.laser_point = {3.75, 0.0};
  const double tight = detection_innovation(state, detection, mount, 0.0).mahalanobis_squared;
  const double loose = detection_innovation(state, detection, mount, 0.01 * 0.01).mahalanobis_squared;
  EXPECT_GT(tight, loose);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
