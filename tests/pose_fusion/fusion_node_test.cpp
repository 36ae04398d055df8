// FusionNode: the per-message decisions pose_fusion's main used to make (which
// fixes are usable, what is counted and logged, the POSE while odometry is silent,
// the heartbeat state).

#include "pose_fusion/fusion_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

constexpr int64_t kT0 = 100'000'000;
constexpr int64_t kPeriod = 10'000;  // odometry at 100 Hz

LaserFixInput fix_at(int64_t utime, const Pose2& pose, FixStatus status = FixStatus::kOk) {
  LaserFixInput in;
  in.utime = utime;
  in.map_T_robot = pose;
  in.covariance = Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal();
  in.status = status;
  in.reflectors_used = 5;
  return in;
}

OdometrySample odometry_at(int k, double distance_per_step = 0.005) {
  return {kT0 + k * kPeriod, {}, Pose2{distance_per_step * k, 0.0, 0.0}, distance_per_step * k};
}

int count(const std::vector<NodeEvent>& events, const std::string& counter) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.counter != nullptr && counter == e.counter;
  }));
}

bool logged(const std::vector<NodeEvent>& events, NodeEvent::Level level, const std::string& text) {
  return std::any_of(events.begin(), events.end(), [&](const NodeEvent& e) {
    return e.level == level && e.log.find(text) != std::string::npos;
  });
}

TEST(UsableFix, OnlyOkAndDegradedWithAFinitePoseAndPositiveCovariance) {
  EXPECT_EQ(usable_fix(fix_at(kT0, Pose2{})).value().quality, FixQuality::kGood);
  EXPECT_EQ(usable_fix(fix_at(kT0, Pose2{}, FixStatus::kDegraded)).value().quality, FixQuality::kUsable);
  EXPECT_FALSE(usable_fix(fix_at(kT0, Pose2{}, FixStatus::kNoPose)));
  EXPECT_FALSE(usable_fix(fix_at(kT0, Pose2{std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0})));
  LaserFixInput zero_variance = fix_at(kT0, Pose2{});
  zero_variance.covariance(2, 2) = 0.0;
  EXPECT_FALSE(usable_fix(zero_variance));
  LaserFixInput infinite = fix_at(kT0, Pose2{});
  infinite.covariance(0, 1) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(usable_fix(infinite));
}

TEST(FusionNode, UnusableFixIsCountedAndNeitherFusedNorPublished) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  EXPECT_FALSE(node.on_fix(fix_at(kT0, Pose2{}, FixStatus::kNoPose), 0));
  EXPECT_EQ(count(node.events(), "fixes_unusable"), 1);
  EXPECT_EQ(node.events().size(), 1u);
  EXPECT_FALSE(node.fusion().initialised());
}

TEST(FusionNode, DegradedFixCannotStartTheFilter) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  node.on_odometry(odometry_at(0), 0);
  node.on_fix(fix_at(kT0, Pose2{}, FixStatus::kDegraded), 1000);
  EXPECT_EQ(count(node.events(), "fixes_not_good_enough_to_start"), 1);
  EXPECT_FALSE(node.fusion().initialised());
}

TEST(FusionNode, GoodFixInitialisesThenPoseIsOkWithItsReflectorCount) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  const FusionOutput& first = node.on_odometry(odometry_at(0), 0);
  EXPECT_EQ(first.status, FusionStatus::kInitializing);
  EXPECT_FALSE(node.health().ok);
  EXPECT_EQ(node.health().detail, "INITIALIZING");
  node.on_fix(fix_at(kT0, Pose2{1.0, 2.0, 0.5}), 1000);
  EXPECT_EQ(count(node.events(), "initialisations"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kInfo, "initialised from the fix at utime 100000000"));
  const FusionOutput& pose = node.on_odometry(odometry_at(1), 10'000);
  EXPECT_EQ(pose.status, FusionStatus::kOk);
  EXPECT_EQ(pose.utime, kT0 + kPeriod);
  EXPECT_EQ(pose.reflectors_used, 5);
  EXPECT_NEAR(pose.map_T_robot.x, 1.0 + 0.005 * std::cos(0.5), 1e-9);
  EXPECT_NEAR(pose.map_T_robot.y, 2.0 + 0.005 * std::sin(0.5), 1e-9);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kInfo, "status INITIALIZING -> OK"));
  EXPECT_TRUE(node.health().ok);
  EXPECT_EQ(node.health().detail, "");
}

TEST(FusionNode, FixFarOffTheEstimateIsGatedAndCounted) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  node.on_odometry(odometry_at(0), 0);
  node.on_fix(fix_at(kT0, Pose2{}), 1000);
  node.on_odometry(odometry_at(1), 10'000);
  node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 0.0, 0.0}), 11'000);
  EXPECT_EQ(count(node.events(), "fixes_rejected_gate"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kDebug, "fix rejected, Mahalanobis^2"));
}

TEST(FusionNode, SilentOdometryPublishesEachNewFixAsDegraded) {
  FusionServiceConfig config;
  config.odometry_timeout = 0.1;
  FusionNode node(config, OdometryNoise{});
  // No odometry at all: the fix is the POSE, DEGRADED, with its own values.
  const std::optional<FusionOutput> alone = node.on_fix(fix_at(kT0, Pose2{1.0, 2.0, 0.5}), 0);
  ASSERT_TRUE(alone);
  EXPECT_EQ(alone->status, FusionStatus::kDegraded);
  EXPECT_EQ(alone->utime, kT0);
  EXPECT_EQ(alone->map_T_robot.x, 1.0);
  EXPECT_EQ(alone->covariance(0, 0), 1e-4);
  EXPECT_EQ(alone->reflectors_used, 5);
  EXPECT_EQ(count(node.events(), "fixes_published_without_odometry"), 1);
  // Odometry flowing: fixes are fused, not published.
  node.on_odometry(odometry_at(1), 1'000'000);
  EXPECT_FALSE(node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 2.0, 0.5}), 1'050'000));
  // Silent for longer than the timeout: a fix newer than the last POSE is published again.
  EXPECT_TRUE(node.on_fix(fix_at(kT0 + 2 * kPeriod, Pose2{1.0, 2.0, 0.5}), 1'200'000));
  EXPECT_FALSE(node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 2.0, 0.5}), 1'300'000));  // older than it
}

TEST(FusionNode, OdometryGoingBackInTimeIsARestartWarning) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  node.on_odometry(odometry_at(10), 0);
  node.on_odometry(odometry_at(5), 10'000);
  EXPECT_EQ(count(node.events(), "odometry_restarts"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kWarn, "ODOMETRY went back in time by 0.050 s"));
}

TEST(FusionNode, OdometryGapAndRestartAreSeamsCountedSeparately) {
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  node.on_fix(fix_at(kT0, Pose2{}), 0);
  node.on_odometry(odometry_at(0), 0);
  node.on_odometry(odometry_at(200), 10'000);  // 2 s later in the same frame
  EXPECT_EQ(count(node.events(), "odometry_gaps"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kWarn, "ODOMETRY resumed after 2.000 s"));
  EXPECT_EQ(node.on_odometry(odometry_at(201), 20'000).status, FusionStatus::kDegraded);
  node.on_odometry({kT0 + 202 * kPeriod, {}, Pose2{}, 0.0}, 30'000);  // distance back to 0: a new frame
  EXPECT_EQ(count(node.events(), "odometry_restarts"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kWarn, "ODOMETRY restarted after 0.010 s"));
}

TEST(FusionNode, EveryFixResultHasItsOwnCounter) {
  EXPECT_STREQ(fix_result_counter(FixResult::kAccepted), "fixes_accepted");
  EXPECT_STREQ(fix_result_counter(FixResult::kInitialised), "initialisations");
  EXPECT_STREQ(fix_result_counter(FixResult::kRejectedGate), "fixes_rejected_gate");
  EXPECT_STREQ(fix_result_counter(FixResult::kTooOld), "fixes_too_old");
  EXPECT_STREQ(fix_result_counter(FixResult::kWaitingForGood), "fixes_not_good_enough_to_start");
  EXPECT_STREQ(fix_result_counter(FixResult::kDeferred), "fixes_deferred");
}

}  // namespace
}  // namespace refloc
