#include "calibration_pairs.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

TEST(CalibrationPairs, WindowsAreConsecutiveAndCloseOnTranslationRotationOrTime) {
  std::vector<TimedPose> fixes;
  for (int i = 0; i < 100; ++i)
    fixes.push_back({i * 20'000, Pose2{0.01 * i, 0.0, 0.0}, Eigen::Matrix3d::Zero()});
  WindowOptions o;
  o.min_translation_m = 0.1;
  const std::vector<FixWindow> windows = select_fix_windows(fixes, o);
  ASSERT_FALSE(windows.empty());
  EXPECT_EQ(windows[0].first, 0u);
  EXPECT_EQ(windows[0].last, 10u);
  for (size_t i = 1; i < windows.size(); ++i) EXPECT_EQ(windows[i].first, windows[i - 1].last);
}

TEST(CalibrationPairs, AGapBetweenFixesStartsANewWindow) {
  std::vector<TimedPose> fixes;
  for (int i = 0; i < 20; ++i)
    fixes.push_back({i * 20'000 + (i >= 5 ? 1'000'000 : 0), Pose2{}, Eigen::Matrix3d::Zero()});
  WindowOptions o;
  o.max_duration_s = 0.1;
  for (const FixWindow& w : select_fix_windows(fixes, o)) EXPECT_GE(w.first, 5u);
}

TEST(CalibrationPairs, InterpolatesAcrossTheHeadingWrapAndRefusesOutsideOrAcrossGaps) {
  const std::vector<TimedPose> s{{0, Pose2{0.0, 0.0, 3.1}, Eigen::Matrix3d::Zero()},
                                 {10'000, Pose2{1.0, 2.0, -3.1}, Eigen::Matrix3d::Zero()}};
  const auto mid = interpolate_pose(s, 5'000, 0.1);
  ASSERT_TRUE(mid);
  EXPECT_NEAR(mid->x, 0.5, 1e-12);
  EXPECT_NEAR(mid->y, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(mid->theta), M_PI, 1e-9);
  EXPECT_FALSE(interpolate_pose(s, 20'000, 0.1));
  EXPECT_FALSE(interpolate_pose(s, -1, 0.1));
  EXPECT_FALSE(interpolate_pose(s, 5'000, 0.001));
}

TEST(CalibrationPairs, RelativePoseCovarianceMatchesMonteCarlo) {
  TimedPose a{0, Pose2{1.0, 2.0, 0.7}, Eigen::Vector3d(4e-6, 9e-6, 1e-6).asDiagonal()};
  TimedPose b{0, Pose2{1.5, 1.0, -0.4}, Eigen::Vector3d(1e-6, 2e-6, 3e-6).asDiagonal()};
  const Eigen::Matrix3d predicted = relative_pose(a, b).covariance;
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Matrix3d sample = Eigen::Matrix3d::Zero();
  const int count = 20000;
  const Pose2 mean = a.pose.inverse() * b.pose;
  for (int i = 0; i < count; ++i) {
    Pose2 pa = a.pose, pb = b.pose;
    pa.x += 2e-3 * n(rng), pa.y += 3e-3 * n(rng), pa.theta += 1e-3 * n(rng);
    pb.x += 1e-3 * n(rng), pb.y += std::sqrt(2e-6) * n(rng), pb.theta += std::sqrt(3e-6) * n(rng);
    const Pose2 r = pa.inverse() * pb;
    const Eigen::Vector3d d(r.x - mean.x, r.y - mean.y, r.theta - mean.theta);
    sample += d * d.transpose() / count;
  }
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(sample(i, i), predicted(i, i), 0.05 * predicted(i, i));
}

TEST(CalibrationPairs, WheelAngleDeltaUndoesTheInt32Wrap) {
  const EncoderSample from{0, {2147483600, 0, -5, 100}};
  const EncoderSample to{0, {-2147483596, 16384, 5, 100}};
  const auto angle = wheel_angle_delta(from, to, 16384);
  EXPECT_NEAR(angle[0], 100.0 * 2.0 * M_PI / 16384, 1e-12);
  EXPECT_NEAR(angle[1], 2.0 * M_PI, 1e-12);
  EXPECT_NEAR(angle[2], 10.0 * 2.0 * M_PI / 16384, 1e-12);
  EXPECT_EQ(angle[3], 0.0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
