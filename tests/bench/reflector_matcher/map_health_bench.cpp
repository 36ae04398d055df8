// Map health's cost per scan in the matcher: keeping the laser scan (on_scan) and turning one OK
// tracking result into evidence (on_match: offsets from fits without each reflector, expected
// reflectors and their line of sight in the scan, unmapped clustering), in the demo hall and in a
// 1000-reflector map; and the 1 Hz report.

#include "reflector_matcher/map_health_monitor.hpp"
#include "reflector_matcher/reflector_matcher.hpp"

#include "synthetic_detections.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace refloc {
namespace {

struct Setup {
  ReflectorMap map;
  std::vector<testing::SyntheticScan> scans;
  std::vector<MatchResult> results;
  LaserScan laser;
};

// 64 tracked OK scans along a loop through the map, with one unmapped detection each, and a
// scan whose beams all reach 15 m (every expected reflector in clear sight).
Setup make_setup(ReflectorMap map, double width, double height) {
  Setup s;
  s.map = std::move(map);
  std::mt19937 rng(7);
  ReflectorMatcher matcher(s.map, MatcherConfig{});
  for (int k = 0; s.scans.size() < 64 && k < 10000; ++k) {
    const double a = 2.0 * M_PI * k / 64.0;
    const Pose2 pose{0.5 * width + 0.3 * width * std::cos(a), 0.5 * height + 0.3 * height * std::sin(a),
                     a + 1.5};
    testing::SyntheticScan scan = testing::render_detections(s.map, pose, testing::SyntheticSensor{}, rng);
    ReflectorDetection unmapped = scan.detections.front();
    unmapped.laser_p_center += Eigen::Vector2d(0.7, 0.4);
    scan.detections.push_back(unmapped);
    const PosePrior prior{pose, Eigen::Vector3d(1e-4, 1e-4, 1e-5).asDiagonal()};
    MatchResult result;
    matcher.match(scan.detections, &prior, result);
    if (result.status != MatchStatus::kOk) continue;
    s.scans.push_back(std::move(scan));
    s.results.push_back(result);
  }
  s.laser.start_angle = -135.0 * M_PI / 180.0;
  s.laser.angle_increment = 0.5 * M_PI / 180.0;
  s.laser.ranges.assign(541, 15.0f);
  return s;
}

void run(benchmark::State& state, const Setup& s) {
  MapHealthMonitor monitor(s.map, SensorVisibilityConfig{}, MapHealthConfig{});
  LaserScan laser = s.laser;
  size_t k = 0, matches = 0;
  for (auto _ : state) {
    const size_t i = k++ % s.scans.size();
    laser.utime = static_cast<int64_t>(k);
    monitor.on_scan(laser);
    monitor.on_match(laser.utime, s.scans[i].detections, s.results[i], true);
    matches += s.results[i].matches.size();
  }
  state.counters["matches_per_scan"] = static_cast<double>(matches) / static_cast<double>(k);
}

void BM_MapHealthPerScanDemoHall(benchmark::State& state) {
  static const Setup s = make_setup(
      load_reflector_map(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json"), 20.0, 12.0);
  run(state, s);
}
BENCHMARK(BM_MapHealthPerScanDemoHall)
    ->Unit(benchmark::kMicrosecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

void BM_MapHealthPerScan1000Reflectors(benchmark::State& state) {
  std::mt19937 rng(3);
  static const Setup s = make_setup(testing::random_map(1000, 200.0, 200.0, 1.0, rng), 200.0, 200.0);
  run(state, s);
}
BENCHMARK(BM_MapHealthPerScan1000Reflectors)->Unit(benchmark::kMicrosecond);

void BM_MapHealthReportDemoHall(benchmark::State& state) {
  static const Setup s = make_setup(
      load_reflector_map(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/map_demo.json"), 20.0, 12.0);
  MapHealthMonitor monitor(s.map, SensorVisibilityConfig{}, MapHealthConfig{});
  for (size_t i = 0; i < 2000; ++i) {  // full windows
    monitor.on_match(0, s.scans[i % s.scans.size()].detections, s.results[i % s.scans.size()], true);
  }
  std::vector<MapHealthChange> changes;
  for (auto _ : state) benchmark::DoNotOptimize(monitor.report(0, 0, changes).reflectors.data());
}
BENCHMARK(BM_MapHealthReportDemoHall)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
