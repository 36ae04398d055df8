#include "reflector_matcher/prior_selector.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace refloc {
namespace {

constexpr int64_t kT0 = 50'000'000;
const Pose2 kMount{0.2, 0.1, 0.0};

PriorSelectionConfig no_startup_window() {
  PriorSelectionConfig c;
  c.relocalize_on_start = 0.0;
  return c;
}

FusedPose fused(int64_t utime, bool ok = true) {
  FusedPose p;
  p.utime = utime;
  p.map_T_robot = {5.0, 3.0, M_PI / 2};
  p.covariance = Eigen::Vector3d(0.01, 0.01, 0.0004).asDiagonal();
  p.ok = ok;
  return p;
}

MatchResult ok_result(MatchMode mode, const Pose2& map_T_laser) {
  MatchResult r;
  r.status = MatchStatus::kOk;
  r.mode = mode;
  r.map_T_laser = map_T_laser;
  return r;
}

TEST(PriorSelector, FreshOkPoseGivesTheMountComposedPriorWithTheCovariancePropagatedThroughTheLeverArm) {
  PriorSelector s(no_startup_window(), kMount);
  s.on_pose(fused(kT0));
  const PriorChoice c = s.select(kT0 + 500'000);  // exactly prior_max_age_s old
  ASSERT_EQ(c.source, PriorSource::kFusedPose);
  ASSERT_TRUE(c.prior);
  // Heading pi/2: the mount (0.2, 0.1) lies at (-0.1, +0.2) in the map.
  EXPECT_NEAR(c.prior->map_T_laser.x, 4.9, 1e-12);
  EXPECT_NEAR(c.prior->map_T_laser.y, 3.2, 1e-12);
  EXPECT_NEAR(c.prior->map_T_laser.theta, M_PI / 2, 1e-12);
  // J(0,2) = -0.2, J(1,2) = -0.1: var_x += 0.04 * 0.0004, var_y += 0.01 * 0.0004.
  EXPECT_NEAR(c.prior->covariance(0, 0), 0.010016, 1e-15);
  EXPECT_NEAR(c.prior->covariance(1, 1), 0.010004, 1e-15);
  EXPECT_NEAR(c.prior->covariance(0, 1), 0.000008, 1e-15);
  EXPECT_NEAR(c.prior->covariance(0, 2), -0.00008, 1e-15);
  EXPECT_NEAR(c.prior->covariance(2, 2), 0.0004, 1e-15);
}

TEST(PriorSelector, NonFiniteFusedCovarianceBecomesZeroSoTheMatcherFloorsTakeOver) {
  FusedPose p = fused(kT0);
  p.covariance(0, 0) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(prior_from_robot_pose(p, kMount).covariance, Eigen::Matrix3d::Zero());
}

TEST(PriorSelector, StaleOrNotOkPoseFallsBackToTheOwnLastOkPoseWithTheConfiguredSigmas) {
  PriorSelector s(no_startup_window(), kMount);
  EXPECT_EQ(s.select(kT0).source, PriorSource::kNone);
  s.on_result(kT0, ok_result(MatchMode::kGlobal, {1.0, 2.0, 0.3}));
  s.on_pose(fused(kT0 - 600'000));  // stale
  PriorChoice c = s.select(kT0 + 20'000);
  ASSERT_EQ(c.source, PriorSource::kOwnPose);
  EXPECT_EQ(c.prior->map_T_laser.x, 1.0);
  EXPECT_EQ(c.prior->map_T_laser.theta, 0.3);
  EXPECT_NEAR(c.prior->covariance(0, 0), 0.09, 1e-15);  // own_prior_sigma_m 0.3
  EXPECT_NEAR(c.prior->covariance(2, 2), std::pow(5.0 * M_PI / 180.0, 2), 1e-15);
  EXPECT_EQ(c.prior->covariance(0, 1), 0.0);
  s.on_pose(fused(kT0 + 20'000, false));  // fresh but DEGRADED
  EXPECT_EQ(s.select(kT0 + 40'000).source, PriorSource::kOwnPose);
  EXPECT_EQ(s.select(kT0 + 500'001).source, PriorSource::kNone);  // own pose too old as well
}

TEST(PriorSelector, OwnPoseIsNotUsedWhenConfiguredOff) {
  PriorSelectionConfig config = no_startup_window();
  config.use_own_pose = false;
  PriorSelector s(config, kMount);
  s.on_result(kT0, ok_result(MatchMode::kGlobal, {1.0, 2.0, 0.3}));
  EXPECT_EQ(s.select(kT0 + 20'000).source, PriorSource::kNone);
}

TEST(PriorSelector, NoPriorInTheStartupWindowUntilAGlobalOkThenTheFusedPose) {
  PriorSelector s(PriorSelectionConfig{}, kMount);  // relocalize_on_start_s 2
  s.on_pose(fused(kT0));
  PriorChoice c = s.select(kT0);
  EXPECT_EQ(c.source, PriorSource::kStartupWindow);
  EXPECT_FALSE(c.prior);
  MatchResult lost;
  EXPECT_EQ(s.on_result(kT0, lost), StartupEvent::kNone);
  EXPECT_EQ(s.select(kT0 + 20'000).source, PriorSource::kStartupWindow);
  EXPECT_EQ(s.on_result(kT0 + 20'000, ok_result(MatchMode::kGlobal, {4.9, 3.2, M_PI / 2})),
            StartupEvent::kRelocalized);
  EXPECT_EQ(s.select(kT0 + 40'000).source, PriorSource::kFusedPose);
  EXPECT_EQ(s.on_result(kT0 + 40'000, ok_result(MatchMode::kTracking, {4.9, 3.2, M_PI / 2})),
            StartupEvent::kNone);
}

TEST(PriorSelector, StartupWindowThatNeverRelocalizesGivesUpOnceAndUsesThePriorAgain) {
  PriorSelector s(PriorSelectionConfig{}, kMount);
  MatchResult lost;
  for (int64_t t = kT0; t <= kT0 + 2'000'000; t += 20'000) {
    EXPECT_EQ(s.select(t).source, PriorSource::kStartupWindow) << t - kT0;
    EXPECT_EQ(s.on_result(t, lost), StartupEvent::kNone);
  }
  s.on_pose(fused(kT0 + 2'020'000));
  EXPECT_EQ(s.select(kT0 + 2'020'000).source, PriorSource::kFusedPose);
  EXPECT_EQ(s.on_result(kT0 + 2'020'000, lost), StartupEvent::kGaveUp);
  EXPECT_EQ(s.select(kT0 + 2'040'000).source, PriorSource::kFusedPose);
  EXPECT_EQ(s.on_result(kT0 + 2'040'000, lost), StartupEvent::kNone);
}

}  // namespace
}  // namespace refloc
