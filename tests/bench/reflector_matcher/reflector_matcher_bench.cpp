// Matcher timing: tracking association per scan, the whole tracking pipeline
// (match + pose solve), global relocalization in maps of 10, 100 and 1000
// reflectors with a realistic density (about 8 reflectors in view), the same
// among racks the map knows (occluders), and the one-off index build.

#include "pose_solver/pose_solver.hpp"
#include "reflector_matcher/reflector_matcher.hpp"
#include "world_renderer/world_loader.hpp"
#include "world_renderer/world_visibility.hpp"

#include "synthetic_detections.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace refloc {
namespace {

/// Side of a square holding n reflectors at the density that puts ~8 in a 20 m, 270 deg view.
double square_side_for(int n) {
  const double view_area = 0.75 * M_PI * 20.0 * 20.0;  // [m^2]
  return std::sqrt(n * view_area / 8.0);
}

struct Scenario {
  ReflectorMap map;
  std::vector<Pose2> poses;
  std::vector<testing::SyntheticScan> scans;
};

/// Random map of n reflectors and 64 poses inside it that see >= 4 reflectors.
Scenario make_scenario(int n, unsigned seed) {
  std::mt19937 rng(seed);
  Scenario s;
  const double side = square_side_for(n);
  s.map = testing::random_map(n, side, side, 1.0, rng);
  std::uniform_real_distribution<double> u(0.0, side), ua(-M_PI, M_PI);
  while (s.poses.size() < 64) {
    const Pose2 pose{u(rng), u(rng), ua(rng)};
    auto scan = testing::render_detections(s.map, pose, testing::SyntheticSensor{}, rng);
    if (scan.detections.size() < 4) continue;
    s.poses.push_back(pose);
    s.scans.push_back(std::move(scan));
  }
  return s;
}

void BM_TrackingMatch(benchmark::State& state) {
  const Scenario s = make_scenario(100, 1);
  ReflectorMatcher matcher(s.map, MatcherConfig{});
  MatchResult result;
  size_t k = 0, detections = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    // Prior 5 cm / 0.5 deg off, as from the fused pose between scans.
    const PosePrior prior{Pose2{s.poses[i].x + 0.05, s.poses[i].y - 0.03, s.poses[i].theta + 0.009},
                          Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal()};
    matcher.match(s.scans[i].detections, &prior, result);
    detections += s.scans[i].detections.size();
    benchmark::DoNotOptimize(result.matches.data());
  }
  state.counters["detections_per_scan"] = static_cast<double>(detections) / static_cast<double>(k);
}
BENCHMARK(BM_TrackingMatch)->Unit(benchmark::kMicrosecond)->Repetitions(5)->ReportAggregatesOnly(true);

void BM_TrackingPipelineMatchAndSolve(benchmark::State& state) {
  const Scenario s = make_scenario(100, 2);
  ReflectorMatcher matcher(s.map, MatcherConfig{});
  PoseSolver solver(SolverConfig{}, Pose2{0.3, 0.0, 0.0});
  MatchResult result;
  PoseSolution solution;
  size_t k = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    const PosePrior prior{Pose2{s.poses[i].x + 0.05, s.poses[i].y - 0.03, s.poses[i].theta + 0.009},
                          Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal()};
    matcher.match(s.scans[i].detections, &prior, result);
    solver.solve(s.scans[i].detections, result.matches, solution);
    benchmark::DoNotOptimize(solution.map_T_robot.x);
  }
}
BENCHMARK(BM_TrackingPipelineMatchAndSolve)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

void BM_GlobalRelocalization(benchmark::State& state) {
  const Scenario s = make_scenario(static_cast<int>(state.range(0)), 3);
  ReflectorMatcher matcher(s.map, MatcherConfig{});
  MatchResult result;
  size_t k = 0, ok = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    matcher.match(s.scans[i].detections, nullptr, result);
    ok += result.status == MatchStatus::kOk;
  }
  state.counters["ok_fraction"] = static_cast<double>(ok) / static_cast<double>(k);
  state.counters["triangles"] = static_cast<double>(matcher.indexed_triangles());
}
BENCHMARK(BM_GlobalRelocalization)->Arg(10)->Arg(100)->Arg(1000)->Unit(benchmark::kMicrosecond);

/// Worst case for triangle lookup: a 32 x 32 grid at 10 m, every triangle repeated hundreds of times.
void BM_GlobalRelocalizationRepetitiveGrid(benchmark::State& state) {
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 32; ++i)
    for (int j = 0; j < 32; ++j) points.emplace_back(10.0 * i, 10.0 * j);
  const ReflectorMap map = testing::map_from_points(points);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> u(0.0, 310.0), ua(-M_PI, M_PI);
  std::vector<testing::SyntheticScan> scans;
  while (scans.size() < 16) {
    auto scan =
        testing::render_detections(map, Pose2{u(rng), u(rng), ua(rng)}, testing::SyntheticSensor{}, rng);
    if (scan.detections.size() >= 4) scans.push_back(std::move(scan));
  }
  ReflectorMatcher matcher(map, MatcherConfig{});
  MatchResult result;
  size_t k = 0, ok = 0;
  for (auto _ : state) {
    matcher.match(scans[k++ % scans.size()].detections, nullptr, result);
    ok += result.status == MatchStatus::kOk;
  }
  state.counters["ok_fraction"] = static_cast<double>(ok) / static_cast<double>(k);
}
BENCHMARK(BM_GlobalRelocalizationRepetitiveGrid)->Unit(benchmark::kMillisecond);

/// n reflectors and n / 2 racks (2 n wall segments) at BM_GlobalRelocalization's density; 64
/// poses outside the racks that see >= 4 reflectors past them. with_racks: the map knows them.
Scenario make_rack_scenario(int n, bool with_racks, unsigned seed) {
  std::mt19937 rng(seed);
  Scenario s;
  const double side = square_side_for(n);
  s.map = testing::random_map(n, side, side, 1.0, rng);
  testing::SyntheticSensor sensor;
  sensor.occluders = testing::random_racks(s.map, n / 2, side, side, rng);
  std::uniform_real_distribution<double> u(0.0, side), ua(-M_PI, M_PI);
  while (s.poses.size() < 64) {
    const Pose2 pose{u(rng), u(rng), ua(rng)};
    if (testing::inside_a_rack(sensor.occluders, pose.translation())) continue;
    auto scan = testing::render_detections(s.map, pose, sensor, rng);
    if (scan.detections.size() < 4) continue;
    s.poses.push_back(pose);
    s.scans.push_back(std::move(scan));
  }
  if (with_racks) s.map.occluders = sensor.occluders;
  return s;
}

/// The demo hall (map_demo_v2.json: its reflectors, and the world's walls, racks and pillars as 20
/// occluder segments), 64 drivable poses that see >= 3 reflectors past them (synthetic detections,
/// no distractors). Without walls: the map without its occluders.
Scenario make_demo_hall_scenario(bool with_walls, unsigned seed) {
  const std::string config_dir = std::string(REFLOC_SOURCE_DIR) + "/deploy/config/";
  const sim::World world = sim::load_world(config_dir + "world_demo.json");
  std::mt19937 rng(seed);
  Scenario s;
  s.map = load_reflector_map(config_dir + "map_demo_v2.json");
  testing::SyntheticSensor sensor;
  sensor.occluders = s.map.occluders;
  std::uniform_real_distribution<double> ux(0.0, 20.0), uy(0.0, 12.0), ua(-M_PI, M_PI);
  while (s.poses.size() < 64) {
    const Pose2 pose{ux(rng), uy(rng), ua(rng)};
    if (!world.is_drivable(pose.translation()) || sim::clearance(world, pose.translation()) < 0.4) continue;
    auto scan = testing::render_detections(s.map, pose, sensor, rng);
    if (scan.detections.size() < 3) continue;
    s.poses.push_back(pose);
    s.scans.push_back(std::move(scan));
  }
  if (!with_walls) s.map.occluders.clear();
  return s;
}

/// Global relocalization of s's scans by the pieces ReflectorMatcher composes, with the occluder
/// grid's cell [cm] as the knob: 0 for a map without occluders (the matcher before them, same
/// scans), 10^8 for one cell (every segment tested per line).
void run_global_relocalization(benchmark::State& state, const Scenario& s, int cell_cm) {
  // The pieces ReflectorMatcher composes, with the grid's cell size as the benchmark's knob.
  const MatcherConfig config;
  const MapGrid grid(s.map, 0.5 * config.sensor.max_range);
  const MapTriangleIndex index(s.map, config.relocalization.side_tolerance,
                               config.relocalization.min_triangle_side,
                               config.relocalization.max_triangle_side,
                               static_cast<size_t>(config.relocalization.max_index_triangles));
  const OccluderGrid occluders(s.map.occluders,
                               cell_cm > 0 ? cell_cm / 100.0 : OccluderGrid::kDefaultCellSize);
  GlobalRelocalizer relocalizer(s.map, grid, index, config.relocalization, config.sensor, config.min_matches,
                                &occluders);
  MatchResult result;
  size_t k = 0, ok = 0, hypotheses = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    relocalizer.relocalize(s.scans[i].detections, result);
    ok += result.status == MatchStatus::kOk;
    hypotheses += relocalizer.hypotheses_verified();
  }
  state.counters["ok_fraction"] = static_cast<double>(ok) / static_cast<double>(k);
  state.counters["hypotheses"] = static_cast<double>(hypotheses) / static_cast<double>(k);
  state.counters["segments"] = static_cast<double>(occluders.segment_count());
}

/// Arg 0: reflectors; arg 1: the occluder grid's cell [cm] (run_global_relocalization).
void BM_GlobalRelocalizationAmongRacks(benchmark::State& state) {
  const int cell_cm = static_cast<int>(state.range(1));
  run_global_relocalization(state, make_rack_scenario(static_cast<int>(state.range(0)), cell_cm > 0, 7),
                            cell_cm);
}
BENCHMARK(BM_GlobalRelocalizationAmongRacks)
    ->ArgsProduct({{100, 1000}, {0, 50, 100, 200, 400, 100000000}})
    ->Unit(benchmark::kMicrosecond);

/// Arg: the occluder grid's cell [cm] (run_global_relocalization).
void BM_GlobalRelocalizationDemoHall(benchmark::State& state) {
  const int cell_cm = static_cast<int>(state.range(0));
  run_global_relocalization(state, make_demo_hall_scenario(cell_cm > 0, 9), cell_cm);
}
BENCHMARK(BM_GlobalRelocalizationDemoHall)
    ->Arg(0)
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Arg(400)
    ->Arg(100000000)
    ->Unit(benchmark::kMicrosecond);

/// Arg: 0 the map without the racks, 1 with them (ReflectorMatcher's own grid).
void BM_TrackingMatchAmongRacks(benchmark::State& state) {
  const Scenario s = make_rack_scenario(1000, state.range(0) != 0, 8);
  ReflectorMatcher matcher(s.map, MatcherConfig{});
  MatchResult result;
  size_t k = 0, ok = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    const PosePrior prior{Pose2{s.poses[i].x + 0.05, s.poses[i].y - 0.03, s.poses[i].theta + 0.009},
                          Eigen::Vector3d(0.01, 0.01, 1e-4).asDiagonal()};
    matcher.match(s.scans[i].detections, &prior, result);
    ok += result.status == MatchStatus::kOk;
  }
  state.counters["ok_fraction"] = static_cast<double>(ok) / static_cast<double>(k);
}
BENCHMARK(BM_TrackingMatchAmongRacks)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

void BM_PaperMatch(benchmark::State& state) {
  const Scenario s = make_scenario(static_cast<int>(state.range(0)), 4);
  MatcherConfig config;
  config.mode = MatcherMode::kPaper;
  ReflectorMatcher matcher(s.map, config);
  MatchResult result;
  size_t k = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.poses.size();
    matcher.match(s.scans[i].detections, nullptr, result);
    benchmark::DoNotOptimize(result.matches.data());
  }
}
BENCHMARK(BM_PaperMatch)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);

void BM_BuildMatcher(benchmark::State& state) {
  std::mt19937 rng(5);
  const int n = static_cast<int>(state.range(0));
  const double side = square_side_for(n);
  const ReflectorMap map = testing::random_map(n, side, side, 1.0, rng);
  for (auto _ : state) {
    ReflectorMatcher matcher(map, MatcherConfig{});
    benchmark::DoNotOptimize(matcher.indexed_triangles());
  }
}
BENCHMARK(BM_BuildMatcher)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

/// The occluder grid of n / 2 racks (2 n segments) over BM_GlobalRelocalization's square for n.
void BM_BuildOccluderGrid(benchmark::State& state) {
  const Scenario s = make_rack_scenario(static_cast<int>(state.range(0)), true, 10);
  for (auto _ : state) {
    OccluderGrid grid(s.map.occluders);
    benchmark::DoNotOptimize(grid.segment_count());
  }
}
BENCHMARK(BM_BuildOccluderGrid)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
