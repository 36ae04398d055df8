#include "fix_truth_check.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

// Fixes that are the truth expanded by 0.04 % about a point and shifted by 1 mm:
// the similarity fit gives back exactly that, with the configured and true mounts undone.
TEST(FixTruthCheck, RecoversAnExpansionOfTheFixesAboutTheDrivesCentroid) {
  const Pose2 configured{0.30, -0.10, 0.0};
  const Pose2 true_mount{0.35, -0.12, 1.5 * M_PI / 180.0};
  std::vector<TimedPose> truth, fixes;
  for (int i = 0; i <= 1000; ++i) {
    const int64_t utime = 1'000'000 + 10'000 * i;
    truth.push_back({utime, Pose2{3.0 + 0.01 * i, 3.0 + std::sin(0.01 * i), 0.002 * i}});
  }
  const Eigen::Vector2d centre(8.0, 3.5);         // any: the fit's translation absorbs the difference
  for (size_t i = 1; i < truth.size(); i += 2) {  // fixes between the truth samples
    const Pose2 p{0.5 * (truth[i - 1].pose.x + truth[i].pose.x),
                  0.5 * (truth[i - 1].pose.y + truth[i].pose.y),
                  0.5 * (truth[i - 1].pose.theta + truth[i].pose.theta)};
    const Eigen::Vector2d expanded =
        centre + 1.0004 * (p.translation() - centre) + Eigen::Vector2d(0.001, 0.0);
    const Pose2 estimate{expanded.x(), expanded.y(), p.theta};
    fixes.push_back(
        {(truth[i - 1].utime + truth[i].utime) / 2, estimate * true_mount * configured.inverse()});
  }
  const FixTruthReport r = compare_fixes_with_truth(fixes, truth, configured, true_mount);
  EXPECT_EQ(r.fixes, 500u);
  EXPECT_NEAR(r.expansion, 4e-4, 2e-6);
  EXPECT_NEAR(r.rotation_rad, 0.0, 1e-6);
  EXPECT_NEAR(r.sigma_theta_rad, 0.0, 1e-9);
  EXPECT_NEAR(r.half_extent_x_m, 5.0, 0.01);
  // A smooth error: consecutive fixes' errors are almost the same.
  EXPECT_GT(r.lag1_correlation, 0.99);
}

TEST(FixTruthCheck, FixesWithoutTruthAroundThemAreLeftOut) {
  const std::vector<TimedPose> truth{{0, Pose2{}}, {10'000, Pose2{}}};
  const std::vector<TimedPose> fixes{{5'000, Pose2{}}, {500'000, Pose2{}}};
  EXPECT_EQ(compare_fixes_with_truth(fixes, truth, Pose2{}, Pose2{}).fixes, 1u);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
