// FusionNode: the per-message decisions pose_fusion's main used to make (which
// fixes are usable, what is counted and logged, the POSE while odometry is silent,
// the heartbeat state).

#include "pose_fusion/fusion_node.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// These tests drive the filter with LASER_POSE alone (detections: detection_fusion_test.cpp).
FusionServiceConfig laser_pose_config() {
  FusionServiceConfig c;
  c.measurements = FusionMeasurements::kLaserPose;
  return c;
}

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

/// The host's wall clock when a message stamped utime arrives: 5 ms later.
int64_t host(int64_t utime) { return utime + 5'000; }

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
  FusionNode node(laser_pose_config(), OdometryNoise{});
  EXPECT_FALSE(node.on_fix(fix_at(kT0, Pose2{}, FixStatus::kNoPose), 0, host(kT0)));
  EXPECT_EQ(count(node.events(), "fixes_unusable"), 1);
  EXPECT_EQ(node.events().size(), 1u);
  EXPECT_FALSE(node.fusion().initialised());
}

TEST(FusionNode, OneDegradedFixCannotStartTheFilterThreeThatAgreeDoWithAWarning) {
  FusionNode node(laser_pose_config(), OdometryNoise{});
  node.on_odometry(odometry_at(0), 0, host(odometry_at(0).utime));
  node.on_fix(fix_at(kT0, Pose2{}, FixStatus::kDegraded), 1000, host(kT0));
  EXPECT_EQ(count(node.events(), "fixes_not_good_enough_to_start"), 1);
  EXPECT_FALSE(node.fusion().initialised());
  // Standing at a spot that shows three reflectors: two more DEGRADED fixes of the same pose.
  node.on_odometry(odometry_at(1, 0.0), 10'000, host(odometry_at(1).utime));
  node.on_fix(fix_at(kT0 + kPeriod, Pose2{}, FixStatus::kDegraded), 11'000, host(kT0 + kPeriod));
  EXPECT_FALSE(node.fusion().initialised());
  node.on_odometry(odometry_at(2, 0.0), 20'000, host(odometry_at(2).utime));
  node.on_fix(fix_at(kT0 + 2 * kPeriod, Pose2{}, FixStatus::kDegraded), 21'000, host(kT0 + 2 * kPeriod));
  EXPECT_TRUE(node.fusion().initialised());
  EXPECT_EQ(count(node.events(), "initialisations_from_degraded_fixes"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kWarn,
                     "initialised from 3 agreeing DEGRADED fixes over 0.02 s"));
}

TEST(FusionNode, GoodFixInitialisesThenPoseIsOkWithItsReflectorCount) {
  FusionNode node(laser_pose_config(), OdometryNoise{});
  const FusionOutput* first = node.on_odometry(odometry_at(0), 0, host(odometry_at(0).utime));
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->status, FusionStatus::kInitializing);
  EXPECT_FALSE(node.health(0).ok);
  EXPECT_EQ(node.health(0).detail, "INITIALIZING");
  node.on_fix(fix_at(kT0, Pose2{1.0, 2.0, 0.5}), 1000, host(kT0));
  EXPECT_EQ(count(node.events(), "initialisations"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kInfo, "initialised from the fix at utime 100000000"));
  const FusionOutput& pose = *node.on_odometry(odometry_at(1), 10'000, host(odometry_at(1).utime));
  EXPECT_EQ(pose.status, FusionStatus::kOk);
  EXPECT_EQ(pose.utime, kT0 + kPeriod);
  EXPECT_EQ(pose.reflectors_used, 5);
  EXPECT_NEAR(pose.map_T_robot.x, 1.0 + 0.005 * std::cos(0.5), 1e-9);
  EXPECT_NEAR(pose.map_T_robot.y, 2.0 + 0.005 * std::sin(0.5), 1e-9);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kInfo, "status INITIALIZING -> OK"));
  EXPECT_TRUE(node.health(10'000).ok);
  EXPECT_EQ(node.health(10'000).detail, "");
}

TEST(FusionNode, FixFarOffTheEstimateIsGatedAndCounted) {
  FusionNode node(laser_pose_config(), OdometryNoise{});
  node.on_odometry(odometry_at(0), 0, host(odometry_at(0).utime));
  node.on_fix(fix_at(kT0, Pose2{}), 1000, host(kT0));
  node.on_odometry(odometry_at(1), 10'000, host(odometry_at(1).utime));
  node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 0.0, 0.0}), 11'000, host(kT0 + kPeriod));
  EXPECT_EQ(count(node.events(), "fixes_rejected_gate"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kDebug, "fix rejected, Mahalanobis^2"));
}

TEST(FusionNode, SilentOdometryPublishesEachNewFixAsDegraded) {
  FusionServiceConfig config = laser_pose_config();
  config.odometry_timeout = 0.1;
  FusionNode node(config, OdometryNoise{});
  // No odometry at all: the fix is the POSE, DEGRADED, with its own values.
  const std::optional<FusionOutput> alone = node.on_fix(fix_at(kT0, Pose2{1.0, 2.0, 0.5}), 0, host(kT0));
  ASSERT_TRUE(alone);
  EXPECT_EQ(alone->status, FusionStatus::kDegraded);
  EXPECT_EQ(alone->utime, kT0);
  EXPECT_EQ(alone->map_T_robot.x, 1.0);
  EXPECT_EQ(alone->covariance(0, 0), 1e-4);
  EXPECT_EQ(alone->reflectors_used, 5);
  EXPECT_EQ(count(node.events(), "fixes_published_without_odometry"), 1);
  // Odometry flowing: fixes are fused, not published.
  node.on_odometry(odometry_at(1), 1'000'000, host(odometry_at(1).utime));
  EXPECT_FALSE(node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 2.0, 0.5}), 1'050'000, host(kT0 + kPeriod)));
  // Silent for longer than the timeout: a fix newer than the last POSE is published again.
  EXPECT_TRUE(
      node.on_fix(fix_at(kT0 + 2 * kPeriod, Pose2{1.0, 2.0, 0.5}), 1'200'000, host(kT0 + 2 * kPeriod)));
  EXPECT_FALSE(node.on_fix(fix_at(kT0 + kPeriod, Pose2{1.0, 2.0, 0.5}), 1'300'000, host(kT0 + kPeriod)));
}

TEST(FusionNode, OdometryClockSteppedBackIsBelievedOnceItPersistsAndIsThenANewFrame) {
  FusionNode node(laser_pose_config(), OdometryNoise{});
  const int64_t stamp0 = odometry_at(10).utime;
  node.on_odometry(odometry_at(10), 0, host(stamp0));
  // The publisher's clock steps back by 1 s: its messages are refused (not newer than the
  // last) until the new clock has held for 10 messages over 0.5 s of host time.
  int refused = 0, restarts = 0, reanchored = 0;
  for (int k = 0; k < 12; ++k) {
    const int64_t stamp = stamp0 - 1'000'000 + k * 100'000;
    refused += node.on_odometry({stamp, {}, Pose2{}, 0.0}, 0, host(stamp0) + k * 100'000) == nullptr;
    restarts += count(node.events(), "odometry_restarts");
    reanchored += count(node.events(), "reanchored_odometry");
    if (k < 9) {
      EXPECT_EQ(count(node.events(), "rejected_odometry_stamp_not_increasing"), 1) << k;
    }
  }
  EXPECT_EQ(refused, 9);
  EXPECT_EQ(reanchored, 1);
  EXPECT_EQ(restarts, 1);
}

TEST(FusionNode, OdometryGapAndRestartAreSeamsCountedSeparately) {
  FusionNode node(laser_pose_config(), OdometryNoise{});
  node.on_fix(fix_at(kT0, Pose2{}), 0, host(kT0));
  node.on_odometry(odometry_at(0), 0, host(odometry_at(0).utime));
  node.on_odometry(odometry_at(200), 10'000, host(odometry_at(200).utime));  // 2 s later in the same frame
  EXPECT_EQ(count(node.events(), "odometry_gaps"), 1);
  EXPECT_TRUE(logged(node.events(), NodeEvent::Level::kWarn, "ODOMETRY resumed after 2.000 s"));
  EXPECT_EQ(node.on_odometry(odometry_at(201), 20'000, host(odometry_at(201).utime))->status,
            FusionStatus::kDegraded);
  node.on_odometry({kT0 + 202 * kPeriod, {}, Pose2{}, 0.0}, 30'000,
                   host(kT0 + 202 * kPeriod));  // distance back to 0: a new frame
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

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
