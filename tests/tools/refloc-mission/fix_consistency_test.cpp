// The NEES of the honest-uncertainty figures (refloc-eval, refloc-mission) on samples with known statistics.
#include "fix_consistency.hpp"

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <random>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

Eigen::Matrix3d correlated_covariance() {
  Eigen::Matrix3d p;
  p << 4e-4, 1.5e-4, 2e-5,  //
      1.5e-4, 1e-4, -1e-5,  //
      2e-5, -1e-5, 3e-5;
  return p;
}

/// Errors drawn from N(bias, scale^2 * P), accumulated against P.
ConsistencySummary sample(double scale, const Eigen::Vector3d& bias, int n, uint64_t seed) {
  const Eigen::Matrix3d p = correlated_covariance();
  const Eigen::Matrix3d l = p.llt().matrixL();
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  ConsistencyAccumulator acc;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d z(normal(rng), normal(rng), normal(rng));
    acc.add(bias + scale * (l * z), p);
  }
  return acc.summary();
}

TEST(FixConsistency, HonestGaussianFixesHaveNeesTwoAndOnePercentOutside) {
  const ConsistencySummary s = sample(1.0, Eigen::Vector3d::Zero(), 20000, 3);
  EXPECT_EQ(s.fixes, 20000);
  EXPECT_EQ(s.unusable_covariances, 0);
  // Standard errors at n = 20000: NEES mean 2/sqrt(10000) = 0.02, share sqrt(.01*.99/n) = 0.0007.
  EXPECT_NEAR(s.position_nees_mean, 2.0, 0.06);
  EXPECT_NEAR(s.position_outside_99, 0.01, 0.0025);
  EXPECT_NEAR(s.heading_nees_mean, 1.0, 0.04);
  EXPECT_NEAR(s.heading_outside_99, 0.01, 0.0025);
}

TEST(FixConsistency, OverConfidentAndBiasedFixesShow) {
  const ConsistencySummary twice = sample(2.0, Eigen::Vector3d::Zero(), 20000, 4);
  EXPECT_NEAR(twice.position_nees_mean, 8.0, 0.3);  // errors twice the claimed sigma
  EXPECT_GT(twice.position_outside_99, 0.25);
  EXPECT_NEAR(twice.heading_nees_mean, 4.0, 0.2);
  // A 20 mm bias in x against a 20 mm sigma (and correlation) adds b^T P^-1 b.
  const Eigen::Vector3d bias(0.02, 0.0, 0.0);
  const double expected =
      2.0 + bias.head<2>().dot(correlated_covariance().topLeftCorner<2, 2>().inverse() * bias.head<2>());
  const ConsistencySummary biased = sample(1.0, bias, 20000, 5);
  EXPECT_NEAR(biased.position_nees_mean, expected, 0.1 * expected);
  EXPECT_NEAR(biased.heading_nees_mean, 1.0, 0.04);
}

TEST(FixConsistency, UnusableCovariancesAreCountedNotAveraged) {
  EXPECT_FALSE(position_nees({0.01, 0.0}, Eigen::Matrix2d::Zero()));
  EXPECT_FALSE(position_nees({NAN, 0.0}, Eigen::Matrix2d::Identity()));
  EXPECT_FALSE(heading_nees(0.01, 0.0));
  EXPECT_NEAR(*position_nees({0.02, 0.0}, Eigen::Matrix2d::Identity() * 1e-4), 4.0, 1e-12);
  EXPECT_NEAR(*heading_nees(0.01, 1e-4), 1.0, 1e-12);
  ConsistencyAccumulator acc;
  acc.add({0.02, 0.0, 0.01}, Eigen::Matrix3d::Identity() * 1e-4);
  acc.add({0.01, 0.0, 0.0}, Eigen::Matrix3d::Zero());
  const ConsistencySummary s = acc.summary();
  EXPECT_EQ(s.fixes, 2);
  EXPECT_EQ(s.unusable_covariances, 1);
  EXPECT_NEAR(s.position_nees_mean, 4.0, 1e-12);
  EXPECT_NEAR(s.heading_nees_mean, 1.0, 1e-12);
  EXPECT_EQ(ConsistencyAccumulator().summary().fixes, 0);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
