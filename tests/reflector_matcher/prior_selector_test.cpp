#include "reflector_matcher/prior_selector.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

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

TEST(PriorSelector, ThePoseStampedAtOrBeforeTheScanIsThePriorWhateverTheArrivalOrder) {
  FusedPose later = fused(kT0 + 30'000);
  later.map_T_robot.x = 5.03;
  for (const bool later_first : {false, true}) {
    PriorSelector s(no_startup_window(), kMount);
    if (later_first) s.on_pose(later);
    s.on_pose(fused(kT0 - 10'000));
    s.on_pose(fused(kT0));
    if (!later_first) s.on_pose(later);
    const PriorChoice c = s.select(kT0 + 20'000);
    ASSERT_EQ(c.source, PriorSource::kFusedPose) << later_first;
    EXPECT_NEAR(c.prior->map_T_laser.x, 4.9, 1e-12) << later_first;  // from the POSE at kT0
  }
  PriorSelector only_later(no_startup_window(), kMount);
  only_later.on_pose(later);
  EXPECT_NEAR(only_later.select(kT0).prior->map_T_laser.x, 4.93,
              1e-12);  // nothing earlier: the earliest after
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

// An INITIAL_POSE (the web console's "Set pose") comes before every other prior, also in the
// startup window; confirmed by a tracked OK scan, after which the own poses beat a POSE still on
// the old place for initial_pose_hold_s; unconfirmed, it expires once and the usual order returns.
TEST(PriorSelector, AnInitialPoseIsThePriorUntilConfirmedThenTheOwnPosesBeatAnOldPose) {
  PriorSelectionConfig config;  // startup window on (2 s)
  PriorSelector s(config, kMount);
  s.on_pose(fused(kT0));  // the fused pose: (5, 3), about to be contradicted
  FusedPose user;
  user.map_T_robot = {12.0, 7.0, 0.0};
  user.covariance = Eigen::Vector3d(0.04, 0.04, 0.0076).asDiagonal();
  s.on_initial_pose(user);
  const PriorChoice first = s.select(kT0 + 20'000);
  ASSERT_EQ(first.source, PriorSource::kInitialPose);
  ASSERT_TRUE(first.prior);
  EXPECT_NEAR(first.prior->map_T_laser.x, 12.2, 1e-12);
  EXPECT_NEAR(first.prior->map_T_laser.y, 7.1, 1e-12);
  s.on_result(kT0 + 20'000, ok_result(MatchMode::kTracking, {12.2, 7.1, 0.0}));
  EXPECT_EQ(s.take_initial_pose_event(), InitialPoseEvent::kConfirmed);
  EXPECT_EQ(s.take_initial_pose_event(), InitialPoseEvent::kNone);  // said once
  s.on_pose(fused(kT0 + 40'000));                                   // fusion still at (5, 3) with status OK
  const PriorChoice next = s.select(kT0 + 40'000);
  EXPECT_EQ(next.source, PriorSource::kOwnPose);
  EXPECT_NEAR(next.prior->map_T_laser.x, 12.2, 1e-12);
  // initial_pose_hold_s (3 s) later the fused POSE is the prior again.
  s.on_result(kT0 + 3'100'000, ok_result(MatchMode::kTracking, {12.2, 7.1, 0.0}));
  s.on_pose(fused(kT0 + 3'100'000));
  EXPECT_EQ(s.select(kT0 + 3'100'000).source, PriorSource::kFusedPose);
}

TEST(PriorSelector, AnInitialPoseNoScanConfirmsExpiresOnceAndTheUsualOrderReturns) {
  PriorSelector s(no_startup_window(), kMount);
  FusedPose user;
  user.map_T_robot = {1.0, 1.0, 0.0};
  user.covariance = Eigen::Vector3d(0.04, 0.04, 0.0076).asDiagonal();
  s.on_initial_pose(user);
  MatchResult lost;
  lost.status = MatchStatus::kLost;
  for (int64_t t = kT0; t <= kT0 + 3'000'000; t += 20'000) {
    ASSERT_EQ(s.select(t).source, PriorSource::kInitialPose) << t - kT0;
    s.on_result(t, lost);
    ASSERT_EQ(s.take_initial_pose_event(), InitialPoseEvent::kNone);
  }
  s.on_pose(fused(kT0 + 3'020'000));
  EXPECT_EQ(s.select(kT0 + 3'020'000).source, PriorSource::kFusedPose);
  EXPECT_EQ(s.take_initial_pose_event(), InitialPoseEvent::kExpired);
  // A global OK while the initial pose is the prior does not confirm it: only a match from it does.
  s.on_initial_pose(user);
  s.select(kT0 + 4'000'000);
  s.on_result(kT0 + 4'000'000, ok_result(MatchMode::kGlobal, {9.0, 9.0, 0.0}));
  EXPECT_EQ(s.take_initial_pose_event(), InitialPoseEvent::kNone);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
