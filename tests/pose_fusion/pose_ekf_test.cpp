#include "pose_fusion/pose_ekf.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace {

TEST(PoseEkf, EqualCovariancesAverageTheMeans) {
  const PoseEstimate prior{{1.0, 2.0, 0.1}, Eigen::Matrix3d::Identity() * 1e-2};
  const PoseEstimate post = ekf_correct(prior, {1.2, 1.8, 0.3}, Eigen::Matrix3d::Identity() * 1e-2);
  EXPECT_NEAR(post.map_T_robot.x, 1.1, 1e-12);
  EXPECT_NEAR(post.map_T_robot.y, 1.9, 1e-12);
  EXPECT_NEAR(post.map_T_robot.theta, 0.2, 1e-12);
  EXPECT_NEAR(post.covariance(0, 0), 5e-3, 1e-12);
}

TEST(PoseEkf, HeadingInnovationIsWrapped) {
  const PoseEstimate prior{{0.0, 0.0, M_PI - 0.05}, Eigen::Matrix3d::Identity() * 1e-2};
  const PoseEstimate post = ekf_correct(prior, {0.0, 0.0, -M_PI + 0.05}, Eigen::Matrix3d::Identity() * 1e-2);
  EXPECT_NEAR(std::abs(post.map_T_robot.theta), M_PI, 1e-12);
  EXPECT_NEAR(mahalanobis_squared(prior, {0.0, 0.0, -M_PI + 0.05}, Eigen::Matrix3d::Identity() * 1e-2),
              0.1 * 0.1 / 2e-2, 1e-12);
}

TEST(PoseEkf, PredictRotatesTheBodyDisplacementIntoTheMap) {
  const PoseEstimate prior{{1.0, 1.0, M_PI / 2.0}, Eigen::Matrix3d::Zero()};
  const Eigen::Matrix3d q = Eigen::Vector3d(1e-4, 4e-4, 0.0).asDiagonal();
  const PoseEstimate post = ekf_predict(prior, {0.1, 0.0, 0.0}, q);
  EXPECT_NEAR(post.map_T_robot.x, 1.0, 1e-12);
  EXPECT_NEAR(post.map_T_robot.y, 1.1, 1e-12);
  EXPECT_NEAR(post.covariance(0, 0), 4e-4, 1e-12);  // body y is map -x now
  EXPECT_NEAR(post.covariance(1, 1), 1e-4, 1e-12);
}

}  // namespace
}  // namespace refloc
