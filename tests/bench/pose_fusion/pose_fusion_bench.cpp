// Cost of the delayed-fix fusion: one odometry step, and one fix arriving
// delay_ms late (rolling back and re-applying delay_ms of 100 Hz odometry).

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"
#include "pose_fusion/pose_fusion.hpp"

#include <benchmark/benchmark.h>

namespace refloc {
namespace {

constexpr int64_t kPeriod = 10'000;

void BM_OdometryStep(benchmark::State& state) {
  PoseFusion fusion{FusionConfig{}};
  fusion.add_fix({kPeriod, Pose2{}, Eigen::Matrix3d::Identity() * 1e-4, FixQuality::kGood});
  const Pose2 delta = se2_exp({0.5, 0.1, 0.3}, 0.01);
  const Eigen::Matrix3d q = increment_covariance(delta, OdometryNoise{});
  int64_t t = kPeriod;
  for (auto _ : state) {
    fusion.add_odometry(t += kPeriod, delta, q);
    benchmark::DoNotOptimize(fusion.estimate());
  }
}
BENCHMARK(BM_OdometryStep);

void BM_DelayedFix(benchmark::State& state) {
  const int64_t delay_us = state.range(0) * 1000;
  PoseFusion fusion{FusionConfig{}};
  fusion.add_fix({kPeriod, Pose2{}, Eigen::Matrix3d::Identity() * 1e-4, FixQuality::kGood});
  const Pose2 delta = se2_exp({0.5, 0.1, 0.3}, 0.01);
  const Eigen::Matrix3d q = increment_covariance(delta, OdometryNoise{});
  int64_t t = kPeriod;
  for (int i = 0; i < 200; ++i) fusion.add_odometry(t += kPeriod, delta, q);
  for (auto _ : state) {
    fusion.add_odometry(t += kPeriod, delta, q);    // keeps the history length steady
    const int64_t fix_time = t - delay_us + 5'000;  // mid-step: includes a split
    // A loose fix at the current estimate: always inside the gate, so every
    // iteration pays the full roll-back and re-application.
    const PoseEstimate& e = fusion.estimate();
    if (fusion.add_fix({fix_time, e.map_T_robot, Eigen::Matrix3d::Identity(), FixQuality::kGood}) !=
        FixResult::kAccepted) {
      state.SkipWithError("fix not accepted");
      break;
    }
    benchmark::DoNotOptimize(fusion.estimate());
  }
}
BENCHMARK(BM_DelayedFix)->Arg(40)->Arg(100)->Arg(500);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
