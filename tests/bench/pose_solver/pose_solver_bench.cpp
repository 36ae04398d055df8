// Solver timing per scan: paper (eq. 4-8) and default (Levenberg-Marquardt with
// outlier test) for 4, 8 and 16 matched reflectors, and the CRLB helper.

#include "pose_solver/crlb.hpp"
#include "pose_solver/pose_solver.hpp"

#include "synthetic_detections.hpp"

#include <benchmark/benchmark.h>

namespace refloc {
namespace {

struct Scan {
  std::vector<ReflectorDetection> detections;
  std::vector<ReflectorMatch> matches;
};

/// n reflectors on a 15 m circle around the robot, all in view.
Scan make_scan(int n, const Pose2& mount) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < n; ++i) {
    const double a = -2.2 + 4.4 * i / std::max(1, n - 1);
    points.emplace_back(20.0 + 15.0 * std::cos(a), 20.0 + 15.0 * std::sin(a) * (1.0 + 0.1 * i / n));
  }
  const ReflectorMap map = testing::map_from_points(points);
  std::mt19937 rng(7);
  const auto synthetic =
      testing::render_detections(map, Pose2{20.0, 20.0, 0.1} * mount, testing::SyntheticSensor{}, rng);
  Scan s;
  s.detections = synthetic.detections;
  for (size_t d = 0; d < synthetic.detections.size(); ++d) {
    const auto& r = map.reflectors[static_cast<size_t>(synthetic.map_index[d])];
    s.matches.push_back({static_cast<int>(d), r.id, r.map_p_center, r.radius});
  }
  return s;
}

void solve_bench(benchmark::State& state, SolverMode mode) {
  const Pose2 mount{0.3, 0.0, 0.0};
  const Scan scan = make_scan(static_cast<int>(state.range(0)), mount);
  SolverConfig config;
  config.mode = mode;
  PoseSolver solver(config, mount);
  PoseSolution solution;
  for (auto _ : state) {
    solver.solve(scan.detections, scan.matches, solution);
    benchmark::DoNotOptimize(solution.map_T_robot.x);
  }
  state.counters["used"] = solution.reflectors_used;
}

void BM_SolveDefault(benchmark::State& state) { solve_bench(state, SolverMode::kDefault); }
void BM_SolvePaper(benchmark::State& state) { solve_bench(state, SolverMode::kPaper); }
BENCHMARK(BM_SolveDefault)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SolvePaper)->Arg(4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);

void BM_Crlb(benchmark::State& state) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(10.0 * std::cos(i), 10.0 * std::sin(i));
  for (auto _ : state) {
    auto crlb = pose_crlb(Pose2{0.5, 0.2, 0.1}, Pose2{0.3, 0, 0}, points, RangeBearingNoise{});
    benchmark::DoNotOptimize(crlb);
  }
}
BENCHMARK(BM_Crlb)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
