#include "pose_fusion/pose_fusion.hpp"

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 100'000'000;
constexpr int64_t kPeriod = 10'000;  // odometry at 100 Hz
const BodyTwist kTwist{0.5, 0.1, 0.3};

Eigen::Matrix3d fix_covariance() { return Eigen::Vector3d(1e-4, 1e-4, 1e-4).asDiagonal(); }

Pose2 odometry_delta(double dt) { return se2_exp(kTwist, dt); }
Eigen::Matrix3d odometry_q(double dt) { return increment_covariance(odometry_delta(dt), OdometryNoise{}); }

// Odometry steps k = first..last, ending at kT0 + k * kPeriod.
void feed(PoseFusion& fusion, int first, int last) {
  for (int k = first; k <= last; ++k) {
    ASSERT_TRUE(fusion.add_odometry(kT0 + k * kPeriod, odometry_delta(0.01), odometry_q(0.01)));
  }
}

PoseFix fix_at(int64_t utime, const Pose2& pose, FixQuality quality = FixQuality::kGood) {
  return {utime, pose, fix_covariance(), quality};
}

// The truth drives a constant twist from the origin at kT0; a fix slightly off it.
Pose2 truth_at(int64_t utime) { return se2_exp(kTwist, 1e-6 * static_cast<double>(utime - kT0)); }
Pose2 biased_fix_pose(int64_t utime) { return truth_at(utime) * Pose2{0.02, -0.01, 0.01}; }

void expect_same(const PoseEstimate& a, const PoseEstimate& b, double tol) {
  EXPECT_NEAR(a.map_T_robot.x, b.map_T_robot.x, tol);
  EXPECT_NEAR(a.map_T_robot.y, b.map_T_robot.y, tol);
  EXPECT_NEAR(a.map_T_robot.theta, b.map_T_robot.theta, tol);
  EXPECT_LE((a.covariance - b.covariance).cwiseAbs().maxCoeff(), tol);
}

PoseFusion started() {
  PoseFusion fusion{FusionConfig{}};
  EXPECT_EQ(fusion.add_fix(fix_at(kT0, Pose2{})), FixResult::kInitialised);
  return fusion;
}

TEST(PoseFusion, DelayedFixAppliedAtItsOwnTimeEqualsTheOnTimeReference) {
  const int64_t fix_time = kT0 + 50 * kPeriod;
  PoseFusion on_time = started();
  feed(on_time, 1, 50);
  EXPECT_EQ(on_time.add_fix(fix_at(fix_time, biased_fix_pose(fix_time))), FixResult::kAccepted);
  feed(on_time, 51, 100);

  PoseFusion delayed = started();
  feed(delayed, 1, 58);  // the fix arrives 80 ms late
  EXPECT_EQ(delayed.add_fix(fix_at(fix_time, biased_fix_pose(fix_time))), FixResult::kAccepted);
  feed(delayed, 59, 100);
  expect_same(delayed.estimate(), on_time.estimate(), 1e-9);

  // Applying the same fix as if it were current is wrong by centimetres.
  PoseFusion naive = started();
  feed(naive, 1, 58);
  naive.add_fix(fix_at(kT0 + 58 * kPeriod, biased_fix_pose(fix_time)));
  feed(naive, 59, 100);
  EXPECT_GT(std::abs(naive.estimate().map_T_robot.x - on_time.estimate().map_T_robot.x), 0.005);
}

TEST(PoseFusion, FixBetweenOdometrySamplesSplitsTheStepExactly) {
  const int64_t fix_time = kT0 + 50 * kPeriod + 4'000;  // 40 % into step 51
  PoseFusion reference = started();
  feed(reference, 1, 50);
  reference.add_odometry(fix_time, odometry_delta(0.004), odometry_q(0.004));
  reference.add_fix(fix_at(fix_time, biased_fix_pose(fix_time)));
  reference.add_odometry(kT0 + 51 * kPeriod, odometry_delta(0.006), odometry_q(0.006));
  feed(reference, 52, 100);

  PoseFusion delayed = started();
  feed(delayed, 1, 57);
  EXPECT_EQ(delayed.add_fix(fix_at(fix_time, biased_fix_pose(fix_time))), FixResult::kAccepted);
  feed(delayed, 58, 100);
  expect_same(delayed.estimate(), reference.estimate(), 1e-9);
}

TEST(PoseFusion, FixesArrivingOutOfOrderGiveTheInOrderResult) {
  const int64_t t1 = kT0 + 30 * kPeriod, t2 = kT0 + 45 * kPeriod;
  PoseFusion in_order = started();
  feed(in_order, 1, 30);
  in_order.add_fix(fix_at(t1, biased_fix_pose(t1)));
  feed(in_order, 31, 45);
  in_order.add_fix(fix_at(t2, biased_fix_pose(t2)));
  feed(in_order, 46, 60);

  PoseFusion swapped = started();
  feed(swapped, 1, 50);
  EXPECT_EQ(swapped.add_fix(fix_at(t2, biased_fix_pose(t2))), FixResult::kAccepted);
  EXPECT_EQ(swapped.add_fix(fix_at(t1, biased_fix_pose(t1))), FixResult::kAccepted);
  feed(swapped, 51, 60);
  expect_same(swapped.estimate(), in_order.estimate(), 1e-9);
}

TEST(PoseFusion, FixPullsTheEstimateAndShrinksTheCovariance) {
  PoseFusion fusion = started();
  feed(fusion, 1, 100);
  const PoseEstimate before = fusion.estimate();
  const int64_t t = kT0 + 100 * kPeriod;
  fusion.add_fix(fix_at(t, biased_fix_pose(t)));
  const PoseEstimate after = fusion.estimate();
  EXPECT_LT(after.covariance.trace(), before.covariance.trace());
  EXPECT_LT(
      std::hypot(after.map_T_robot.x - biased_fix_pose(t).x, after.map_T_robot.y - biased_fix_pose(t).y),
      std::hypot(before.map_T_robot.x - biased_fix_pose(t).x, before.map_T_robot.y - biased_fix_pose(t).y));
}

TEST(PoseFusion, OutlierFixIsRejectedByTheGate) {
  PoseFusion fusion = started();
  feed(fusion, 1, 20);
  const PoseEstimate before = fusion.estimate();
  const int64_t t = kT0 + 20 * kPeriod;
  EXPECT_EQ(fusion.add_fix(fix_at(t, truth_at(t) * Pose2{0.5, 0.0, 0.0})), FixResult::kRejectedGate);
  EXPECT_GT(fusion.last_mahalanobis_squared(), 16.27);
  expect_same(fusion.estimate(), before, 0.0);
  EXPECT_EQ(fusion.consecutive_rejections(), 1);
  // A consistent fix right after is accepted and resets the count.
  EXPECT_EQ(fusion.add_fix(fix_at(t, biased_fix_pose(t))), FixResult::kAccepted);
  EXPECT_LT(fusion.last_mahalanobis_squared(), 16.27);
  EXPECT_EQ(fusion.consecutive_rejections(), 0);
}

TEST(PoseFusion, StatusDegradesAfterOneSecondAndIsLostAfterFiveWithoutFixes) {
  PoseFusion fusion{FusionConfig{}};
  EXPECT_EQ(fusion.status(kT0), FusionStatus::kInitializing);
  fusion.add_fix(fix_at(kT0, Pose2{}));
  feed(fusion, 1, 600);
  EXPECT_EQ(fusion.status(kT0 + 1'000'000), FusionStatus::kOk);
  EXPECT_EQ(fusion.status(kT0 + 1'010'000), FusionStatus::kDegraded);
  EXPECT_EQ(fusion.status(kT0 + 5'000'000), FusionStatus::kDegraded);
  EXPECT_EQ(fusion.status(kT0 + 5'010'000), FusionStatus::kLost);
  // Lost: a merely usable fix is not enough, a good one re-initialises without the gate.
  const int64_t t = kT0 + 600 * kPeriod;
  EXPECT_EQ(fusion.add_fix(fix_at(t, Pose2{9.0, 9.0, 1.0}, FixQuality::kUsable)), FixResult::kWaitingForGood);
  EXPECT_EQ(fusion.add_fix(fix_at(t, Pose2{9.0, 9.0, 1.0})), FixResult::kInitialised);
  EXPECT_EQ(fusion.status(t), FusionStatus::kOk);
  EXPECT_NEAR(fusion.estimate().map_T_robot.x, 9.0, 1e-12);
}

TEST(PoseFusion, ConsecutiveRejectionsMakeItLostAndTheNextGoodFixReinitialises) {
  FusionConfig config;
  config.max_consecutive_rejections = 5;
  PoseFusion fusion{config};
  fusion.add_fix(fix_at(kT0, Pose2{}));
  feed(fusion, 1, 10);
  const int64_t t = kT0 + 10 * kPeriod;
  const Pose2 kidnapped{4.0, -2.0, 2.0};  // the robot was carried away
  for (int i = 0; i < 4; ++i) EXPECT_EQ(fusion.add_fix(fix_at(t, kidnapped)), FixResult::kRejectedGate);
  EXPECT_EQ(fusion.status(t), FusionStatus::kOk);
  EXPECT_EQ(fusion.add_fix(fix_at(t, kidnapped)), FixResult::kRejectedGate);
  EXPECT_EQ(fusion.status(t), FusionStatus::kLost);
  EXPECT_EQ(fusion.add_fix(fix_at(t, kidnapped)), FixResult::kInitialised);
  EXPECT_TRUE(approx_equal(fusion.estimate().map_T_robot, kidnapped, 1e-12, 1e-12));
  EXPECT_EQ(fusion.status(t), FusionStatus::kOk);
}

TEST(PoseFusion, InitialisesFromTheFirstGoodFixAndRollsItForward) {
  PoseFusion fusion{FusionConfig{}};
  feed(fusion, 1, 35);  // odometry running before any fix
  EXPECT_EQ(fusion.status(kT0 + 35 * kPeriod), FusionStatus::kInitializing);
  const int64_t t = kT0 + 30 * kPeriod;
  EXPECT_EQ(fusion.add_fix(fix_at(t, truth_at(t), FixQuality::kUsable)), FixResult::kWaitingForGood);
  EXPECT_EQ(fusion.add_fix(fix_at(t, truth_at(t))), FixResult::kInitialised);
  // The 50 ms of odometry after the fix time were re-applied on top of it.
  EXPECT_TRUE(approx_equal(fusion.estimate().map_T_robot, truth_at(kT0 + 35 * kPeriod), 1e-12, 1e-12));
  EXPECT_EQ(fusion.utime(), kT0 + 35 * kPeriod);
}

TEST(PoseFusion, ThreeDegradedFixesThatAgreeThroughTheOdometryStartIt) {
  // A pose_fusion restarted where the laser sees three reflectors: only DEGRADED fixes come,
  // each a little after its time, while the robot drives on.
  PoseFusion fusion{FusionConfig{}};
  int fed = 0;
  const auto usable = [&](int k, const Pose2& pose) {
    feed(fusion, fed + 1, k + 3);
    fed = k + 3;
    return fusion.add_fix(fix_at(kT0 + k * kPeriod, pose, FixQuality::kUsable));
  };
  EXPECT_EQ(usable(100, truth_at(kT0 + 100 * kPeriod)), FixResult::kWaitingForGood);
  EXPECT_EQ(usable(150, Pose2{9.0, 9.0, 1.0}), FixResult::kWaitingForGood);           // agrees with nothing
  EXPECT_EQ(usable(200, truth_at(kT0 + 200 * kPeriod)), FixResult::kWaitingForGood);  // 2 of 3
  EXPECT_EQ(fusion.status(kT0 + 203 * kPeriod), FusionStatus::kInitializing);
  EXPECT_EQ(usable(390, truth_at(kT0 + 390 * kPeriod)), FixResult::kInitialised);
  EXPECT_EQ(fusion.start_agreeing_fixes(), 3);
  EXPECT_NEAR(fusion.start_span_s(), 2.9, 1e-9);
  EXPECT_TRUE(approx_equal(fusion.estimate().map_T_robot, truth_at(kT0 + 393 * kPeriod), 1e-9, 1e-9));
  EXPECT_EQ(usable(395, truth_at(kT0 + 395 * kPeriod)), FixResult::kAccepted);  // now it corrects
}

TEST(PoseFusion, DegradedFixesThatDoNotFollowTheOdometryNeverStartIt) {
  // The same pose reported while the robot drives away: the fixes disagree once carried along;
  // and with start_agreeing_usable_fixes 0 even agreeing ones wait for an OK fix.
  FusionConfig ok_only;
  ok_only.start_agreeing_usable_fixes = 0;
  PoseFusion fusion{FusionConfig{}}, strict{ok_only};
  for (int k = 100; k <= 400; k += 20) {
    feed(fusion, k - 19, k);
    feed(strict, k - 19, k);
    const int64_t t = kT0 + k * kPeriod;
    EXPECT_EQ(fusion.add_fix(fix_at(t, Pose2{2.0, 1.0, 0.5}, FixQuality::kUsable)),
              FixResult::kWaitingForGood)
        << k;
    EXPECT_EQ(strict.add_fix(fix_at(t, truth_at(t), FixQuality::kUsable)), FixResult::kWaitingForGood) << k;
  }
}

TEST(PoseFusion, FixOlderThanTheHistoryIsRefused) {
  PoseFusion fusion = started();
  feed(fusion, 1, 150);  // 1.5 s; history is 1 s
  EXPECT_EQ(fusion.add_fix(fix_at(kT0 + 20 * kPeriod, truth_at(kT0 + 20 * kPeriod))), FixResult::kTooOld);
  EXPECT_EQ(fusion.add_fix(fix_at(kT0 + 80 * kPeriod, truth_at(kT0 + 80 * kPeriod))), FixResult::kAccepted);
}

TEST(PoseFusion, OdometryOutOfOrderIsIgnored) {
  PoseFusion fusion = started();
  feed(fusion, 1, 3);
  EXPECT_FALSE(fusion.add_odometry(kT0 + 2 * kPeriod, odometry_delta(0.01), odometry_q(0.01)));
  EXPECT_EQ(fusion.utime(), kT0 + 3 * kPeriod);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
