// Where a scan cannot tell the range offset b from the pose: b is held, its sigma goes into the
// covariance, and the fix says so. And the filter that keeps b across scans.

#include "pose_solver/pose_solver.hpp"
#include "pose_solver/range_bias_filter.hpp"
#include "pose_solver/solver_node.hpp"

#include "solver_scenario.hpp"

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>
#include <string>

namespace refloc {
namespace REFLOC_UNITY_ID {  // per file: a folder's tests compile as one unit

/// True when a - b is positive semidefinite (a at least as uncertain as b in every direction).
bool at_least_as_uncertain(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(a - b);
  return eig.eigenvalues().minCoeff() >= -1e-12;
}

PoseSolution solve_with(const SolverConfig& config, const testing::SyntheticScan& scan,
                        const std::vector<ReflectorMatch>& matches) {
  PoseSolver solver(config, testing::corner_mount());
  PoseSolution solution;
  solver.solve(scan.detections, matches, solution);
  return solution;
}

TEST(RangeBiasGeometry, ThreeReflectorsHoldTheBiasInflateTheCovarianceAndSaySo) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(61);
  const auto scan = testing::render_detections(map, Pose2{7.0, 5.0, 0.0} * testing::corner_mount(),
                                               testing::SyntheticSensor{}, rng);
  auto matches = testing::true_matches(scan, map);
  matches.resize(3);
  const PoseSolution held = solve_with(SolverConfig{}, scan, matches);
  SolverConfig exact;
  exact.range_bias.estimate = false;
  exact.range_bias.prior_sigma = 0.0;
  const PoseSolution plain = solve_with(exact, scan, matches);
  ASSERT_EQ(held.status, SolveStatus::kDegraded);
  EXPECT_EQ(held.range_bias_use, RangeBiasUse::kFewReflectors);
  EXPECT_EQ(held.range_bias, 0.0);
  EXPECT_EQ(held.range_bias_sigma, 0.03);
  EXPECT_TRUE(approx_equal(held.map_T_robot, plain.map_T_robot, 1e-7, 1e-7));
  EXPECT_TRUE(at_least_as_uncertain(held.covariance, plain.covariance));
  const double held_trace = held.covariance.block(0, 0, 2, 2).trace();
  const double plain_trace = plain.covariance.block(0, 0, 2, 2).trace();
  EXPECT_GT(held_trace, 1.5 * plain_trace);

  const LaserFix fix = make_laser_fix(1, MatchVerdict::kOk, held, 3);
  EXPECT_TRUE(fix.range_bias_unestimable());
  EXPECT_NE(std::string(fix.range_bias_detail()).find("too few reflectors"), std::string::npos);
  std::map<std::string, int64_t> counters;
  fix.for_each_counter([&](const char* name, int64_t by) { counters[name] += by; });
  EXPECT_EQ(counters["range_bias_unestimable_fixes"], 1);
}

TEST(RangeBiasGeometry, ReflectorsInANarrowConeCannotTellTheBiasFromADistance) {
  // Four reflectors 10-11 m ahead within +-3 degrees: a common range offset looks like a step
  // forward, so the scan's own sigma of b is far above 20 mm.
  const ReflectorMap map = testing::map_from_points({{10.0, -0.5}, {10.5, 0.1}, {11.0, 0.6}, {10.2, 0.3}});
  std::mt19937 rng(62);
  testing::SyntheticSensor sensor;
  sensor.shadowing = false;
  const auto scan = testing::render_detections(map, Pose2{0.0, 0.0, 0.0}, sensor, rng);
  ASSERT_EQ(scan.detections.size(), 4u);
  PoseSolver solver(SolverConfig{}, Pose2{});
  PoseSolution solution;
  solver.solve(scan.detections, testing::true_matches(scan, map), solution);
  ASSERT_NE(solution.status, SolveStatus::kLost);
  std::printf("narrow cone: the scan alone gives b a sigma of %.0f mm\n",
              1e3 * solution.range_bias_scan_sigma);
  EXPECT_EQ(solution.range_bias_use, RangeBiasUse::kWeakGeometry);
  EXPECT_GT(solution.range_bias_scan_sigma, 0.02);
  EXPECT_EQ(solution.range_bias_sigma, 0.03);
  const LaserFix fix = make_laser_fix(1, MatchVerdict::kOk, solution, 4);
  EXPECT_NE(std::string(fix.range_bias_detail()).find("not spread"), std::string::npos);
}

TEST(RangeBiasGeometry, TheHallEstimatesItAndTheNodeKeepsItAcrossScans) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(63);
  SolverNode node(SolverConfig{}, testing::corner_mount());
  double last_sigma = 1.0;
  for (int i = 0; i < 20; ++i) {
    const auto scan = testing::render_detections(map, Pose2{7.0, 5.0, 0.3} * testing::corner_mount(),
                                                 testing::SyntheticSensor{}, rng);
    const LaserFix& fix = node.on_matches(1'000'000 + 20'000 * i, MatchVerdict::kOk, scan.detections,
                                          testing::true_matches(scan, map));
    ASSERT_TRUE(fix.ok());
    EXPECT_EQ(fix.range_bias_use, RangeBiasUse::kEstimated);
    EXPECT_STREQ(fix.range_bias_detail(), "");
    EXPECT_LT(node.range_bias().sigma(), last_sigma);  // each scan adds information
    last_sigma = node.range_bias().sigma();
  }
  EXPECT_EQ(node.range_bias().updates(), 20);
  EXPECT_LT(node.range_bias().sigma(), 0.0015);
}

TEST(RangeBiasGeometry, TheHeartbeatCarriesTheKeptEstimateAndWhyItWasNotEstimated) {
  const ReflectorMap map = testing::hall_map();
  std::mt19937 rng(64);
  SolverNode node(SolverConfig{}, testing::corner_mount());
  std::map<std::string, int64_t> gauges;
  const auto scan = [&] {
    auto s = testing::render_detections(map, Pose2{7.0, 5.0, 0.3} * testing::corner_mount(),
                                        testing::SyntheticSensor{}, rng);
    for (ReflectorDetection& d : s.detections)
      d.laser_p_center *= (d.laser_p_center.norm() + 0.02) / d.laser_p_center.norm();
    return s;
  };
  constexpr int64_t kT0 = 1'700'000'000'000'000, kPeriod = 20'000;
  for (int k = 1; k <= 50; ++k) {
    const auto s = scan();
    const SolverOutput& out = node.on_message(kT0 + k * kPeriod, k, MatchVerdict::kOk, s.detections,
                                              testing::true_matches(s, map), kT0 + k * kPeriod + 3'000);
    ASSERT_TRUE(out.accepted);
    EXPECT_STREQ(out.ok_detail(), "");
    out.for_each_gauge([&](const char* name, int64_t value) { gauges[name] = value; });
  }
  std::printf("heartbeat after 50 scans at +20 mm: range_bias_um %lld, range_bias_sigma_um %lld\n",
              static_cast<long long>(gauges["range_bias_um"]),
              static_cast<long long>(gauges["range_bias_sigma_um"]));
  EXPECT_NEAR(static_cast<double>(gauges["range_bias_um"]), 20'000.0, 3.0 * gauges["range_bias_sigma_um"]);
  EXPECT_LT(gauges["range_bias_sigma_um"], 1'500);
  // A scan of three reflectors: DEGRADED (min_reflectors_ok), b held at the kept estimate.
  auto s = scan();
  auto matches = testing::true_matches(s, map);
  matches.resize(3);
  const SolverOutput& out = node.on_message(kT0 + 51 * kPeriod, 51, MatchVerdict::kOk, s.detections, matches,
                                            kT0 + 51 * kPeriod + 3'000);
  ASSERT_TRUE(out.fix->has_pose);
  EXPECT_TRUE(out.fix->range_bias_unestimable());
  EXPECT_NEAR(out.fix->range_bias, 1e-6 * static_cast<double>(gauges["range_bias_um"]), 1e-5);
}

TEST(RangeBiasFilter, GrowsWithTheDriftUpToThePriorAndAnOlderStampAddsNoTime) {
  RangeBiasConfig config;
  config.drift = 1e-3;  // [m/sqrt(s)]
  RangeBiasFilter filter(config);
  RangeBiasPrior p = filter.prior_at(1'000'000);
  EXPECT_EQ(p.mean, 0.0);
  EXPECT_EQ(p.sigma, 0.03);
  EXPECT_TRUE(p.estimate);
  filter.update(0.025, 0.002);
  p = filter.prior_at(5'000'000);  // 4 s: variance + 1e-6 * 4
  EXPECT_EQ(p.mean, 0.025);
  EXPECT_NEAR(p.sigma, std::sqrt(0.002 * 0.002 + 4e-6), 1e-12);
  const double sigma = p.sigma;
  EXPECT_EQ(filter.prior_at(2'000'000).sigma, sigma);                  // back in time: no drift
  EXPECT_EQ(filter.prior_at(5'000'000 + 10'000'000'000).sigma, 0.03);  // capped at the prior
  filter.update(std::nan(""), 0.001);                                  // refused
  EXPECT_EQ(filter.mean(), 0.025);
  EXPECT_EQ(filter.updates(), 1);
}

}  // namespace REFLOC_UNITY_ID
}  // namespace refloc
