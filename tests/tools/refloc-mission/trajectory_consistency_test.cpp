// consistency_against_truth: the NEES refloc-mission reports for POSE and LASER_POSE, on a
// synthetic drive whose published errors are drawn from the covariance the fixes carry.

#include "trajectory_consistency.hpp"

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr int64_t kTruthPeriodUs = 10'000;  // GROUND_TRUTH at 100 Hz, as robot_sim sends it

/// A 1 m/s drive turning at 0.5 rad/s for duration_s, sampled at 100 Hz.
Trajectory curved_drive(double duration_s) {
  Trajectory truth;
  for (int64_t t = 0; t <= static_cast<int64_t>(duration_s * 1e6); t += kTruthPeriodUs) {
    const double s = static_cast<double>(t) * 1e-6;
    truth.add(t, {2.0 * std::sin(0.5 * s), 2.0 * (1.0 - std::cos(0.5 * s)), wrap_angle(0.5 * s)});
  }
  return truth;
}

Eigen::Matrix3d correlated_covariance() {  // 8 mm / 5 mm, correlated; 6 mrad heading
  Eigen::Matrix3d p;
  p << 64e-6, 20e-6, 5e-6,  //
      20e-6, 25e-6, -2e-6,  //
      5e-6, -2e-6, 36e-6;
  return p;
}

/// Fixes at 50 Hz stamped between truth samples (3 ms after), each the truth at its stamp
/// plus scale * N(0, P), published with P.
std::vector<StampedFix> noisy_fixes(const Trajectory& truth, double scale, uint64_t seed) {
  const Eigen::Matrix3d p = correlated_covariance();
  const Eigen::Matrix3d l = p.llt().matrixL();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<StampedFix> fixes;
  for (int64_t t = 3'000; t < truth.samples().back().utime; t += 20'000) {
    const Pose2 map_T_true = *truth.at(t);
    const Eigen::Vector3d e = scale * (l * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
    fixes.push_back(
        {t, {map_T_true.x + e.x(), map_T_true.y + e.y(), wrap_angle(map_T_true.theta + e.z())}, p});
  }
  return fixes;
}

TEST(TrajectoryConsistency, HonestFixesAlongACurvedDriveHaveNeesTwoAndOne) {
  const Trajectory truth = curved_drive(200.0);  // 10,000 fixes, heading wraps several times
  const ConsistencySummary s = consistency_against_truth(noisy_fixes(truth, 1.0, 7), truth);
  EXPECT_EQ(s.fixes, 10000);
  EXPECT_EQ(s.unusable_covariances, 0);
  // Standard errors at n = 10000: position mean 2/sqrt(5000) = 0.028, heading sqrt(2/n) = 0.014,
  // share outside sqrt(0.01 * 0.99 / n) = 0.001. The truth's linear interpolation over 10 ms on a
  // 2 m radius is off by < 7 um, nothing against a 5 mm sigma.
  EXPECT_NEAR(s.position_nees_mean, 2.0, 0.09);
  EXPECT_NEAR(s.position_outside_99, 0.01, 0.003);
  EXPECT_NEAR(s.heading_nees_mean, 1.0, 0.05);
  EXPECT_NEAR(s.heading_outside_99, 0.01, 0.003);
}

TEST(TrajectoryConsistency, ErrorsTwiceTheClaimedSigmaGiveFourTimesTheNees) {
  const Trajectory truth = curved_drive(200.0);
  const ConsistencySummary s = consistency_against_truth(noisy_fixes(truth, 2.0, 8), truth);
  EXPECT_NEAR(s.position_nees_mean, 8.0, 0.4);
  EXPECT_NEAR(s.heading_nees_mean, 4.0, 0.2);
  // P(chi2_2 > 9.21 / 4) = exp(-9.21 / 8) = 0.316; P(chi2_1 > 6.63 / 4) = 0.198.
  EXPECT_NEAR(s.position_outside_99, 0.316, 0.02);
  EXPECT_NEAR(s.heading_outside_99, 0.198, 0.02);
}

TEST(TrajectoryConsistency, MatchesTheTruthAtTheFixStampAndSkipsUncoveredFixes) {
  Trajectory truth;
  truth.add(0, {0.0, 0.0, M_PI - 0.01});
  truth.add(10'000, {0.01, 0.0, -M_PI + 0.01});                              // heading crosses +-pi
  const Eigen::Matrix3d p = Eigen::Vector3d(1e-6, 1e-6, 1e-6).asDiagonal();  // 1 mm, 1 mrad
  const std::vector<StampedFix> fixes = {
      {5'000, {0.005 + 0.002, 0.001, M_PI}, p},  // truth there (0.005, 0, pi): NEES 4 + 1, heading 0
      {-1, {0.0, 0.0, 0.0}, p},                  // before the truth: not counted
      {20'000, {0.0, 0.0, 0.0}, p},              // after the truth: not counted
      {2'000, {9.0, 9.0, 0.0}, p},               // before from_utime below: not counted
  };
  const ConsistencySummary s = consistency_against_truth(fixes, truth, 4'000);
  EXPECT_EQ(s.fixes, 1);
  EXPECT_NEAR(s.position_nees_mean, 5.0, 1e-6);
  EXPECT_NEAR(s.heading_nees_mean, 0.0, 1e-9);
  EXPECT_EQ(s.position_outside_99, 0.0);
}

// "max while driving": an error while the truth stands still counts in max_xy_m only.
TEST(TrajectoryCompare, TheMovingMaximumLeavesOutTheRobotStandingStill) {
  Trajectory truth, estimate;
  for (int k = 0; k <= 200; ++k) {  // 1 s standing at 0, then 1 s at 1 m/s along x, 100 Hz
    const int64_t t = k * 10000;
    const double x = k <= 100 ? 0.0 : (k - 100) * 0.01;
    truth.add(t, {x, 0.0, 0.0});
    const double error = k == 50 ? 0.006 : (k == 150 ? 0.004 : 0.001);
    estimate.add(t, {x, error, 0.0});
  }
  const ErrorStats stats = compare(estimate, truth);
  EXPECT_NEAR(stats.max_xy_m, 0.006, 1e-12);
  EXPECT_NEAR(stats.max_xy_moving_m, 0.004, 1e-12);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
