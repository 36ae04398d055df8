// Monte Carlo of the range offset b (measured - true range): synthetic detections of the hall
// with Gaussian noise and a constant offset, through the solver library (PoseSolver for one
// scan, SolverNode for the estimate kept across scans), no LCM.

#include "pose_solver/pose_solver.hpp"
#include "pose_solver/solver_node.hpp"

#include "solver_scenario.hpp"

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <cstdio>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

constexpr double kChi2TwoDof99 = 9.21;

/// Every detection's range lengthened by offset [m], as a biased LMS100 would report it.
testing::SyntheticScan offset_scan(testing::SyntheticScan scan, double offset) {
  for (ReflectorDetection& d : scan.detections) {
    const double r = d.laser_p_center.norm();
    d.laser_p_center *= (r + offset) / r;
    d.range += offset;
  }
  return scan;
}

struct PositionStats {
  int n = 0;
  double nees_sum = 0.0;
  int outside_99 = 0;
  Eigen::Vector2d error_sum = Eigen::Vector2d::Zero();
  double error2_sum = 0.0;
  double max_abs_x = 0.0, max_abs_y = 0.0;

  void add(const Pose2& estimate, const Eigen::Matrix3d& covariance, const Pose2& truth) {
    const Eigen::Vector2d e(estimate.x - truth.x, estimate.y - truth.y);
    const double nees = e.dot(covariance.topLeftCorner<2, 2>().inverse() * e);
    ++n;
    nees_sum += nees;
    outside_99 += nees > kChi2TwoDof99 ? 1 : 0;
    error_sum += e;
    error2_sum += e.squaredNorm();
    max_abs_x = std::max(max_abs_x, std::abs(e.x()));
    max_abs_y = std::max(max_abs_y, std::abs(e.y()));
  }
  double nees() const { return nees_sum / n; }
  double outside() const { return static_cast<double>(outside_99) / n; }
  double rms_mm() const { return 1e3 * std::sqrt(error2_sum / n); }
  void print(const char* what) const {
    std::printf(
        "%s: position NEES %.3f (2 expected), %.2f %% outside the 99 %% ellipse, RMS %.2f mm, "
        "mean error (%.2f, %.2f) mm, max |x| %.1f |y| %.1f mm, %d scans\n",
        what, nees(), 100.0 * outside(), rms_mm(), 1e3 * error_sum.x() / n, 1e3 * error_sum.y() / n,
        1e3 * max_abs_x, 1e3 * max_abs_y, n);
  }
};

SolverConfig config_with(bool estimate) {
  SolverConfig c;
  c.range_bias.estimate = estimate;
  return c;
}

/// Random poses in the hall's middle, scans 0.1 s apart through one SolverNode (b kept across scans).
PositionStats run_node(bool estimate, double offset, int scans, unsigned seed, RangeBiasFilter* filter_out) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(3, 13), uy(3, 9), ua(-M_PI, M_PI);
  SolverNode node(config_with(estimate), testing::corner_mount());
  PositionStats stats;
  for (int i = 0; i < scans; ++i) {
    const Pose2 truth{ux(rng), uy(rng), ua(rng)};
    const auto scan = offset_scan(
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng),
        offset);
    const LaserFix& fix = node.on_matches(1'000'000 + 100'000 * i, MatchVerdict::kOk, scan.detections,
                                          testing::true_matches(scan, map));
    EXPECT_TRUE(fix.has_pose);
    if (!fix.has_pose) continue;
    stats.add(fix.map_T_robot, fix.covariance, truth);
  }
  if (filter_out) *filter_out = node.range_bias();
  return stats;
}

TEST(RangeBiasMonteCarlo, EstimatedAcrossScansTheBiasIsRecoveredAndThePoseIsConsistent) {
  for (double offset : {0.03, -0.03, 0.0}) {
    RangeBiasFilter filter{RangeBiasConfig{}};
    const PositionStats s = run_node(true, offset, 3000, 51, &filter);
    char what[96];
    std::snprintf(what, sizeof what, "estimation on, offset %+.0f mm, b = %.2f +- %.2f mm", 1e3 * offset,
                  1e3 * filter.mean(), 1e3 * filter.sigma());
    s.print(what);
    EXPECT_NEAR(filter.mean(), offset, 3.0 * filter.sigma() + 1e-4);
    EXPECT_LT(filter.sigma(), 0.002);
    EXPECT_GE(s.nees(), 1.5);
    EXPECT_LE(s.nees(), 2.5);
    EXPECT_LE(s.outside(), 0.02);
    EXPECT_LT(std::abs(s.error_sum.x() / s.n), 0.0005);
    EXPECT_LT(std::abs(s.error_sum.y() / s.n), 0.0005);
  }
}

TEST(RangeBiasMonteCarlo, NotEstimatedThePriorSigmaInTheCovarianceKeepsItHonest) {
  for (double offset : {0.03, -0.03}) {
    const PositionStats s = run_node(false, offset, 2000, 52, nullptr);
    char what[64];
    std::snprintf(what, sizeof what, "estimation off, offset %+.0f mm", 1e3 * offset);
    s.print(what);
    EXPECT_GE(s.nees(), 1.5);
    EXPECT_LE(s.nees(), 2.5);
    EXPECT_LE(s.outside(), 0.02);
  }
  // No offset: the inflation is unused, the covariance conservative, never over-confident.
  const PositionStats zero = run_node(false, 0.0, 2000, 52, nullptr);
  zero.print("estimation off, offset +0 mm");
  EXPECT_LE(zero.nees(), 2.5);
  EXPECT_LE(zero.outside(), 0.02);
}

TEST(RangeBiasMonteCarlo, WithoutAnOffsetTheEstimateCostsNoAccuracy) {
  // Today's solver: b known to be 0 (prior sigma 0, not estimated).
  SolverConfig exact = config_with(false);
  exact.range_bias.prior_sigma = 0.0;
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(53);
  std::uniform_real_distribution<double> ux(3, 13), uy(3, 9), ua(-M_PI, M_PI);
  SolverNode today(exact, testing::corner_mount()), estimating(config_with(true), testing::corner_mount());
  PositionStats a, b;
  for (int i = 0; i < 3000; ++i) {
    const Pose2 truth{ux(rng), uy(rng), ua(rng)};
    const auto scan =
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng);
    const auto matches = testing::true_matches(scan, map);
    const int64_t utime = 1'000'000 + 100'000 * i;
    const LaserFix& fa = today.on_matches(utime, MatchVerdict::kOk, scan.detections, matches);
    ASSERT_TRUE(fa.has_pose);
    a.add(fa.map_T_robot, fa.covariance, truth);
    const LaserFix& fb = estimating.on_matches(utime, MatchVerdict::kOk, scan.detections, matches);
    ASSERT_TRUE(fb.has_pose);
    b.add(fb.map_T_robot, fb.covariance, truth);
  }
  a.print("b known to be 0 (today's solver)");
  b.print("b estimated, offset 0");
  EXPECT_LT(b.rms_mm(), 1.05 * a.rms_mm());
}

TEST(RangeBiasMonteCarlo, OneScanAloneGivesAnUnbiasedPoseAndABiasWithinItsSigma) {
  const ReflectorMap map = testing::hall_map();
  const Pose2 truth{7.0, 5.0, 0.4};
  const double offset = 0.03;
  std::mt19937 rng(54);
  PoseSolver solver(config_with(true), testing::corner_mount());  // the config's prior every scan
  PoseSolution solution;
  PositionStats s;
  double b_sum = 0.0, b_z2_sum = 0.0;
  const int draws = 2000;
  for (int i = 0; i < draws; ++i) {
    const auto scan = offset_scan(
        testing::render_detections(map, truth * testing::corner_mount(), testing::SyntheticSensor{}, rng),
        offset);
    solver.solve(scan.detections, testing::true_matches(scan, map), solution);
    ASSERT_EQ(solution.status, SolveStatus::kOk);
    ASSERT_EQ(solution.range_bias_use, RangeBiasUse::kEstimated);
    s.add(solution.map_T_robot, solution.covariance, truth);
    b_sum += solution.range_bias;
    b_z2_sum += std::pow((solution.range_bias - offset) / solution.range_bias_sigma, 2);
  }
  s.print("one scan, offset +30 mm, fixed pose");
  const double b_mean = b_sum / draws, b_z2 = b_z2_sum / draws;
  std::printf(
      "one scan: mean b %.2f mm (30 true), mean ((b - 30 mm) / sigma_b)^2 %.3f (1 expected), sigma_b %.2f "
      "mm\n",
      1e3 * b_mean, b_z2, 1e3 * solution.range_bias_sigma);
  // The posterior mean is shrunk towards the prior's 0 by sigma_p^2 / (sigma_p^2 + sigma_scan^2).
  const double prior_sigma = RangeBiasConfig{}.prior_sigma, scan_sigma = solution.range_bias_scan_sigma;
  const double expected_mean =
      offset * prior_sigma * prior_sigma / (prior_sigma * prior_sigma + scan_sigma * scan_sigma);
  const double standard_error = scan_sigma / std::sqrt(draws);
  std::printf("one scan: expected posterior mean %.2f mm (scan sigma %.2f mm)\n", 1e3 * expected_mean,
              1e3 * scan_sigma);
  EXPECT_NEAR(b_mean, expected_mean, 4.0 * standard_error);
  EXPECT_NEAR(b_z2, 1.0, 0.15);
  EXPECT_GE(s.nees(), 1.5);
  EXPECT_LE(s.nees(), 2.5);
  EXPECT_LE(s.outside(), 0.02);
  const double position_sigma = std::sqrt(solution.covariance(0, 0));
  EXPECT_LT(std::abs(s.error_sum.x() / draws), 4.0 * position_sigma / std::sqrt(draws));
  EXPECT_LT(std::abs(s.error_sum.y() / draws), 4.0 * std::sqrt(solution.covariance(1, 1) / draws));
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
