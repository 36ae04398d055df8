// Cost of the delayed-measurement fusion: one odometry step; one fix arriving delay_ms
// late (rolling back and re-applying delay_ms of 100 Hz odometry); and what one 50 Hz scan
// costs the service with detections: two ODOMETRY messages and one REFLECTOR_MATCHES of
// N matched detections 20 ms late, through FusionNode (checks, counters, filter).

#include "common/odometry_noise.hpp"
#include "common/se2.hpp"
#include "pose_fusion/fusion_node.hpp"
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

/// in's reflectors on a 10 m circle around map_T_robot and its detections as seen from there,
/// in place (no allocation in the timed loop; the robot drives kilometres in it).
void place_matches(MatchesInput& in, const Pose2& map_T_robot, int64_t utime, int64_t counter) {
  in.utime = utime;
  in.scan_counter = counter;
  const Pose2 laser_T_map = (map_T_robot * Pose2{0.3, 0.0, 0.0}).inverse();
  const int n = static_cast<int>(in.matches.size());
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    Eigen::Vector2d& m = in.matches[static_cast<size_t>(i)].map_p_center;
    m = {map_T_robot.x + 10.0 * std::cos(a), map_T_robot.y + 10.0 * std::sin(a)};
    ReflectorDetection& d = in.detections[static_cast<size_t>(i)];
    d.laser_p_center = laser_T_map * m;
    d.range = d.laser_p_center.norm();
    d.bearing = std::atan2(d.laser_p_center.y(), d.laser_p_center.x());
  }
}

/// The matches of a robot at map_T_robot seeing n reflectors on a 10 m circle around it.
MatchesInput matches_around(const Pose2& map_T_robot, int64_t utime, int64_t counter, int n) {
  MatchesInput in;
  in.matcher_ok = true;
  for (int i = 0; i < n; ++i) {
    in.matches.push_back({i, i + 1, Eigen::Vector2d::Zero(), 0.06});
    ReflectorDetection d;
    d.covariance = Eigen::Matrix2d::Identity() * 1e-5;
    in.detections.push_back(d);
  }
  place_matches(in, map_T_robot, utime, counter);
  return in;
}

void BM_ScanCycleWithDetections(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  FusionNode node(FusionServiceConfig{}, OdometryNoise{});
  const double speed = 1.0;  // [m/s] along x
  int64_t t = 1'000'000'000;
  int k = 0;
  const auto odometry = [&] {
    t += kPeriod;
    ++k;
    const double x = speed * k * kPeriod * 1e-6;
    node.on_odometry({t, {speed, 0.0, 0.0}, Pose2{x, 0.0, 0.0}, x}, t, t + 2'000);
  };
  const auto truth = [&](int64_t at) {
    return Pose2{speed * static_cast<double>(at - 1'000'010'000) * 1e-6, 0, 0};
  };
  odometry();
  LaserFixInput fix;
  fix.utime = t;
  fix.map_T_robot = truth(t);
  fix.covariance = Eigen::Matrix3d::Identity() * 1e-4;
  fix.status = FixStatus::kOk;
  node.on_fix(fix, t, t + 2'000);
  int64_t counter = 0;
  for (int i = 0; i < 100; ++i) {  // a full history, as in service
    odometry();
    odometry();
    node.on_matches(matches_around(truth(t - 2 * kPeriod), t - 2 * kPeriod, ++counter, n), t, t + 3'000);
  }
  MatchesInput in = matches_around(Pose2{}, 0, 0, n);
  int64_t accepted = 0;
  for (auto _ : state) {
    odometry();
    odometry();
    place_matches(in, truth(t - 2 * kPeriod), t - 2 * kPeriod, ++counter);
    node.on_matches(in, t, t + 3'000);
    for (const NodeEvent& e : node.events())
      if (e.counter != nullptr && std::string(e.counter) == "scans_accepted") ++accepted;
  }
  if (accepted != static_cast<int64_t>(state.iterations())) state.SkipWithError("a scan was not accepted");
}
BENCHMARK(BM_ScanCycleWithDetections)->Arg(4)->Arg(8)->Arg(16);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
