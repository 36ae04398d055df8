// pose_fusion across a restart of mecanum_odometry: the new odometry frame starts
// at the origin with distance 0, and the robot kept moving while nobody counted.
#include "pose_fusion/odometry_continuity.hpp"
#include "pose_fusion/odometry_silence.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 100'000'000;
constexpr int64_t kOdomPeriod = 10'000;  // 100 Hz
constexpr int64_t kScanPeriod = 20'000;  // 50 Hz
const BodyTwist kTwist{0.8, 0.2, 0.3};

Pose2 truth_at(int64_t utime) {
  return Pose2{3.0, 2.0, 0.5} * se2_exp(kTwist, 1e-6 * static_cast<double>(utime - kT0));
}

Eigen::Matrix3d fix_covariance() { return Eigen::Vector3d(2.5e-5, 2.5e-5, 1e-5).asDiagonal(); }

/// pose_fusion's main loop without LCM: odometry messages through OdometryContinuity into PoseFusion.
class FusionHarness {
 public:
  FusionHarness() : fusion_(FusionConfig{}) {}

  /// An ODOMETRY message of an odometry service that started at odom_start_utime (its origin).
  void odometry(int64_t utime, int64_t odom_start_utime) {
    const Pose2 odom_T_robot = truth_at(odom_start_utime).inverse() * truth_at(utime);
    const double distance =
        std::hypot(kTwist.vx, kTwist.vy) * 1e-6 * static_cast<double>(utime - odom_start_utime);
    const OdometryStep step = continuity_.next({utime, {}, odom_T_robot, distance});
    last_kind = step.kind;
    const Eigen::Matrix3d q = increment_covariance(step.delta, OdometryNoise{});
    if (step.kind == OdometryStepKind::kContinuous) fusion_.add_odometry(utime, step.delta, q);
    if (step.kind == OdometryStepKind::kSeam)
      fusion_.add_odometry_seam(utime, step.delta, q + step.unobserved_q);
  }
  FixResult fix(int64_t utime) {
    return fusion_.add_fix({utime, truth_at(utime), fix_covariance(), FixQuality::kGood});
  }
  double error_m(int64_t utime) const {
    const Pose2 e = fusion_.estimate().map_T_robot, t = truth_at(utime);
    return std::hypot(e.x - t.x, e.y - t.y);
  }
  PoseFusion& fusion() { return fusion_; }
  OdometryStepKind last_kind = OdometryStepKind::kFirst;

 private:
  OdometryContinuity continuity_;
  PoseFusion fusion_;
};

TEST(OdometryContinuity, ContinuousMessagesGiveTheBodyFrameDisplacement) {
  OdometryContinuity c;
  EXPECT_EQ(c.next({kT0, {}, Pose2{1.0, 0.0, 0.0}, 1.0}).kind, OdometryStepKind::kFirst);
  const OdometryStep s = c.next({kT0 + kOdomPeriod, {}, Pose2{1.0, 0.01, 0.05}, 1.01});
  EXPECT_EQ(s.kind, OdometryStepKind::kContinuous);
  EXPECT_NEAR(s.delta.x, 0.0, 1e-12);
  EXPECT_NEAR(s.delta.y, 0.01, 1e-12);
  EXPECT_NEAR(s.delta.theta, 0.05, 1e-12);
  EXPECT_FALSE(s.restarted);
}

TEST(OdometryContinuity, DistanceGoingBackIsARestartWithNoDisplacementAndTheUnobservedMotionAsCovariance) {
  OdometryContinuity c;  // bounds 1.5 m/s, 1.5 rad/s
  c.next({kT0, {}, Pose2{5.0, 4.0, 1.0}, 12.0});
  const OdometryStep s = c.next({kT0 + 400'000, {}, Pose2{}, 0.0});
  EXPECT_EQ(s.kind, OdometryStepKind::kSeam);
  EXPECT_TRUE(s.restarted);
  EXPECT_NEAR(s.gap, 0.4, 1e-12);
  EXPECT_TRUE(approx_equal(s.delta, Pose2{}, 0.0, 0.0));
  EXPECT_NEAR(s.unobserved_q(0, 0), 0.36, 1e-12);  // (0.4 s * 1.5 m/s)^2
  EXPECT_NEAR(s.unobserved_q(2, 2), 0.36, 1e-12);
}

TEST(OdometryContinuity, LongGapInOneFrameKeepsTheDisplacementButAddsUncertainty) {
  OdometryContinuity c;
  c.next({kT0, {}, Pose2{1.0, 0.0, 0.0}, 1.0});
  const OdometryStep s = c.next({kT0 + 1'500'000, {}, Pose2{2.0, 0.0, 0.0}, 2.0});
  EXPECT_EQ(s.kind, OdometryStepKind::kSeam);
  EXPECT_FALSE(s.restarted);
  EXPECT_NEAR(s.delta.x, 1.0, 1e-12);
  EXPECT_GT(s.unobserved_q(0, 0), 1.0);
}

TEST(OdometryContinuity, TimeGoingBackStartsANewFrameWithoutAStep) {
  OdometryContinuity c;
  c.next({kT0, {}, Pose2{1.0, 0.0, 0.0}, 1.0});
  EXPECT_EQ(c.next({kT0 - 5'000, {}, Pose2{}, 0.0}).kind, OdometryStepKind::kBackwards);
  EXPECT_EQ(c.next({kT0 + 5'000, {}, Pose2{0.001, 0.0, 0.0}, 0.001}).kind, OdometryStepKind::kContinuous);
}

// The robot drives at ~0.8 m/s; odometry dies at 1 s, a new odometry service
// publishes from 1.4 s on in its own frame; laser fixes (40 ms late) never stop.
TEST(PoseFusion, OdometryRestartWhileMovingIsReanchoredByTheFixesOfTheOutageWithoutAJump) {
  FusionHarness h;
  const int64_t kill = kT0 + 1'000'000, restart = kT0 + 1'400'000;
  int64_t next_scan = kT0;
  double max_error = 0.0;
  int accepted_or_deferred = 0;
  for (int64_t t = kT0; t <= kT0 + 2'500'000; t += kOdomPeriod) {
    if (t < kill) h.odometry(t, kT0);
    if (t >= restart) h.odometry(t, restart);
    if (t == restart) {
      EXPECT_EQ(h.last_kind, OdometryStepKind::kSeam);  // no continuous step across services
    }
    while (next_scan + 40'000 <= t) {  // the fix for a scan arrives 40 ms after it
      const FixResult r = h.fix(next_scan);
      accepted_or_deferred +=
          r == FixResult::kAccepted || r == FixResult::kDeferred || r == FixResult::kInitialised;
      EXPECT_NE(r, FixResult::kRejectedGate) << "scan at " << next_scan - kT0;
      next_scan += kScanPeriod;
    }
    if (h.fusion().initialised() && (t < kill || t > restart + kOdomPeriod)) {
      max_error = std::max(max_error, h.error_m(t));
      if (t > restart + kOdomPeriod) {
        EXPECT_EQ(h.fusion().status(t), FusionStatus::kOk) << t - kT0;
      }
    }
  }
  EXPECT_LT(max_error, 0.02);
  EXPECT_EQ(h.fusion().deferred_fixes(), 0U);
  EXPECT_GT(accepted_or_deferred, 100);
}

TEST(PoseFusion, OdometryRestartWithoutFixesIsDegradedUntilTheNextFixWhichTheGateAccepts) {
  FusionHarness h;
  ASSERT_EQ(h.fix(kT0), FixResult::kInitialised);
  for (int64_t t = kT0 + kOdomPeriod; t <= kT0 + 500'000; t += kOdomPeriod) h.odometry(t, kT0);
  h.fix(kT0 + 480'000);
  const int64_t restart = kT0 + 800'000;  // 0.3 s outage, ~0.25 m driven unseen
  h.odometry(restart, restart);
  EXPECT_EQ(h.last_kind, OdometryStepKind::kSeam);
  h.odometry(restart + kOdomPeriod, restart);
  EXPECT_EQ(h.fusion().status(restart + kOdomPeriod), FusionStatus::kDegraded);
  EXPECT_GT(h.error_m(restart + kOdomPeriod), 0.15);
  for (int64_t t = restart + 2 * kOdomPeriod; t <= restart + 5 * kOdomPeriod; t += kOdomPeriod)
    h.odometry(t, restart);
  EXPECT_EQ(h.fix(restart + 3 * kOdomPeriod), FixResult::kAccepted);
  EXPECT_EQ(h.fusion().status(restart + 5 * kOdomPeriod), FusionStatus::kOk);
  EXPECT_LT(h.error_m(restart + 5 * kOdomPeriod), 0.01);
}

TEST(PoseFusion, FixWellAheadOfOdometryWaitsForItInsteadOfBeingGatedAgainstAStaleEstimate) {
  FusionHarness h;
  ASSERT_EQ(h.fix(kT0), FixResult::kInitialised);
  for (int64_t t = kT0 + kOdomPeriod; t <= kT0 + 100'000; t += kOdomPeriod) h.odometry(t, kT0);
  // 0.2 s ahead: against the estimate at 0.1 s that is 16 cm off, far outside the gate.
  EXPECT_EQ(h.fix(kT0 + 300'000), FixResult::kDeferred);
  EXPECT_EQ(h.fusion().deferred_fixes(), 1U);
  for (int64_t t = kT0 + 110'000; t <= kT0 + 310'000; t += kOdomPeriod) h.odometry(t, kT0);
  EXPECT_EQ(h.fusion().deferred_fixes(), 0U);
  ASSERT_EQ(h.fusion().deferred_results().size(), 0U);  // applied by the step that reached it, at 0.3 s
  EXPECT_EQ(h.fusion().consecutive_rejections(), 0);
  EXPECT_LT(h.error_m(kT0 + 310'000), 0.005);
}

TEST(OdometrySilence, FixesBecomePoseOnlyWhileOdometryIsSilentAndNeverGoBackInTime) {
  OdometrySilence s(0.1);
  EXPECT_TRUE(s.publish_fix(0, kT0));  // no odometry ever yet
  s.on_odometry(1'000'000, kT0 + 100'000);
  EXPECT_FALSE(s.publish_fix(1'050'000, kT0 + 110'000));  // odometry alive: POSE comes from it
  // Odometry dies: fixes take over after 0.1 s ...
  EXPECT_FALSE(s.publish_fix(1'090'000, kT0 + 150'000));
  EXPECT_TRUE(s.publish_fix(1'110'000, kT0 + 170'000));
  EXPECT_FALSE(s.publish_fix(1'130'000, kT0 + 170'000));  // the same time again: no
  EXPECT_TRUE(s.publish_fix(1'150'000, kT0 + 190'000));
  // ... until the restarted odometry publishes again.
  s.on_odometry(1'400'000, kT0 + 400'000);
  EXPECT_FALSE(s.publish_fix(1'410'000, kT0 + 410'000));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
