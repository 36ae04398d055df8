#include "reflector_extractor/fix_velocity_estimator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kT0 = 1'700'000'000'000'000;
constexpr int64_t kPeriod_us = 20'000;  // LMS100 at 50 Hz

/// The OK fix at kT0 + k periods of a robot holding twist from start.
LaserPoseFix fix_on_arc(const Pose2& start, const BodyTwist& twist, int k) {
  LaserPoseFix f;
  f.utime = kT0 + k * kPeriod_us;
  f.map_T_robot = start * se2_exp(twist, static_cast<double>(k * kPeriod_us) * 1e-6);
  f.covariance = Eigen::Matrix3d::Identity() * 1e-5;
  f.ok = true;
  return f;
}

TEST(FixVelocityEstimator, ConstantBodyTwistOnAnArcIsRecoveredFromNoiseFreeFixes) {
  const BodyTwist twist{0.8, 0.2, 0.5};
  FixVelocityEstimator estimator;  // window 0.3 s: 16 fixes
  for (int k = 0; k < 40; ++k) estimator.add(fix_on_arc({3.0, 2.0, 1.0}, twist, k));
  const FixVelocityEstimate e = estimator.estimate(kT0 + 40 * kPeriod_us);
  ASSERT_EQ(e.status, FixVelocityStatus::kOk);
  EXPECT_EQ(e.fixes, 16);
  // The chord of an arc is shorter than the arc: over 0.3 s at 0.5 rad/s the slope is
  // sin(x)/x = 0.99906 of the speed (0.78 mm/s here); the heading rate is exact.
  EXPECT_NEAR(e.twist.vx, 0.8, 1e-3);
  EXPECT_NEAR(e.twist.vy, 0.2, 1e-3);
  EXPECT_NEAR(e.twist.wz, 0.5, 1e-9);
  EXPECT_LT(e.rms_residual, 2e-3);
  EXPECT_NEAR(e.newest_age_s, 0.02, 1e-12);
}

TEST(FixVelocityEstimator, HeadingThroughPlusMinusPiIsUnwrapped) {
  const BodyTwist twist{0.5, 0.0, 1.0};
  FixVelocityEstimator estimator;
  for (int k = 0; k < 16; ++k) estimator.add(fix_on_arc({0.0, 0.0, M_PI - 0.15}, twist, k));
  const FixVelocityEstimate e = estimator.estimate(kT0 + 15 * kPeriod_us);
  ASSERT_EQ(e.status, FixVelocityStatus::kOk);
  EXPECT_NEAR(e.twist.wz, 1.0, 1e-9);
  EXPECT_NEAR(e.twist.vx, 0.5, 2e-3);
  EXPECT_NEAR(e.twist.vy, 0.0, 1e-9);
}

TEST(FixVelocityEstimator, NoisyFixesGiveTheTwistWithinTheLineFitsSpread) {
  // 5 mm and 2 mrad per fix (a driving fix's honest sigma): a line through 16 fixes over
  // 0.3 s has sigma_v = 5 mm * sqrt(12 / (16 * 0.3^2)) = 14 mm/s.
  const BodyTwist twist{0.8, 0.0, 0.0};
  std::mt19937_64 rng(7);
  std::normal_distribution<double> xy(0.0, 0.005), heading(0.0, 0.002);
  double sum_vx2 = 0.0, sum_vy2 = 0.0, sum_wz2 = 0.0;
  const int trials = 400;
  for (int trial = 0; trial < trials; ++trial) {
    FixVelocityEstimator estimator;
    for (int k = 0; k < 16; ++k) {
      LaserPoseFix f = fix_on_arc({1.0, 1.0, 0.3}, twist, k);
      f.map_T_robot.x += xy(rng);
      f.map_T_robot.y += xy(rng);
      f.map_T_robot.theta += heading(rng);
      estimator.add(f);
    }
    const FixVelocityEstimate e = estimator.estimate(kT0 + 16 * kPeriod_us);
    ASSERT_TRUE(e.ok()) << to_string(e.status);
    sum_vx2 += std::pow(e.twist.vx - 0.8, 2);
    sum_vy2 += std::pow(e.twist.vy, 2);
    sum_wz2 += std::pow(e.twist.wz, 2);
  }
  EXPECT_NEAR(std::sqrt(sum_vx2 / trials), 0.0144, 0.003);
  EXPECT_NEAR(std::sqrt(sum_vy2 / trials), 0.0144, 0.003);
  EXPECT_NEAR(std::sqrt(sum_wz2 / trials), 0.0058, 0.0012);  // 2 mrad * sqrt(12 / 1.44)
}

TEST(FixVelocityEstimator, NoFixesOrAStaleNewestFixGiveNoEstimate) {
  FixVelocityEstimator estimator;
  EXPECT_EQ(estimator.estimate(kT0).status, FixVelocityStatus::kNoFixes);
  for (int k = 0; k < 16; ++k) estimator.add(fix_on_arc({}, {0.8, 0.0, 0.0}, k));
  const int64_t newest = kT0 + 15 * kPeriod_us;
  EXPECT_EQ(estimator.estimate(newest + 200'000).status, FixVelocityStatus::kOk);
  EXPECT_EQ(estimator.estimate(newest + 200'001).status, FixVelocityStatus::kStale);
  EXPECT_EQ(estimator.estimate(newest - 200'001).status, FixVelocityStatus::kStale);
}

TEST(FixVelocityEstimator, TooFewFixesOrTooShortASpanGiveNoEstimate) {
  FixVelocityEstimator estimator;
  for (int k = 0; k < 4; ++k) estimator.add(fix_on_arc({}, {0.8, 0.0, 0.0}, k));
  EXPECT_EQ(estimator.estimate(kT0 + 4 * kPeriod_us).status, FixVelocityStatus::kTooFew);
  estimator.add(fix_on_arc({}, {0.8, 0.0, 0.0}, 4));  // 5 fixes over 0.08 s: the minimum
  EXPECT_EQ(estimator.estimate(kT0 + 5 * kPeriod_us).status, FixVelocityStatus::kOk);

  FixVelocityConfig dense;
  dense.min_span_s = 0.1;
  FixVelocityEstimator short_span(dense);
  for (int k = 0; k < 5; ++k) short_span.add(fix_on_arc({}, {0.8, 0.0, 0.0}, k));
  EXPECT_EQ(short_span.estimate(kT0 + 5 * kPeriod_us).status, FixVelocityStatus::kTooFew);
}

TEST(FixVelocityEstimator, FixesThatAreNotOkOrNotNewerAreIgnored) {
  FixVelocityEstimator estimator;
  for (int k = 0; k < 10; ++k) {
    LaserPoseFix f = fix_on_arc({}, {0.8, 0.0, 0.0}, k);
    f.ok = k % 2 == 0;
    estimator.add(f);
  }
  EXPECT_EQ(estimator.fixes(), 5);
  estimator.add(fix_on_arc({}, {0.8, 0.0, 0.0}, 8));  // same stamp as the newest
  EXPECT_EQ(estimator.fixes(), 5);
}

TEST(FixVelocityEstimator, AJumpFasterThanTheRobotCanMoveStartsTheWindowOver) {
  FixVelocityEstimator estimator;
  for (int k = 0; k < 10; ++k) estimator.add(fix_on_arc({}, {0.8, 0.0, 0.0}, k));
  LaserPoseFix jumped = fix_on_arc({}, {0.8, 0.0, 0.0}, 10);
  jumped.map_T_robot.y += 0.2;  // 0.2 m in 20 ms = 10 m/s: a relocalization, not motion
  estimator.add(jumped);
  EXPECT_EQ(estimator.fixes(), 1);
  EXPECT_EQ(estimator.estimate(jumped.utime).status, FixVelocityStatus::kTooFew);
}

TEST(FixVelocityEstimator, FixesScatteredAboutTheLineGiveNoEstimate) {
  FixVelocityEstimator estimator;
  for (int k = 0; k < 16; ++k) {
    LaserPoseFix f = fix_on_arc({}, {0.0, 0.0, 0.0}, k);
    f.map_T_robot.x += k % 2 == 0 ? 0.04 : -0.04;  // 4 cm either side: 4 m/s steps, still plausible
    estimator.add(f);
  }
  const FixVelocityEstimate e = estimator.estimate(kT0 + 16 * kPeriod_us);
  EXPECT_EQ(e.status, FixVelocityStatus::kScattered);
  EXPECT_NEAR(e.rms_residual, 0.04, 1e-3);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
