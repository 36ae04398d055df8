// Rendering cost of one LMS100 scan (541 beams) in the demo hall (24 reflectors,
// ~40 segments), static and moving, and how it scales with the beam sub-rays.

#include "world_renderer/scan_renderer.hpp"
#include "world_renderer/world_loader.hpp"

#include <benchmark/benchmark.h>

namespace {

using refloc::LaserScan;
using refloc::Pose2;
using namespace refloc::sim;

const World& demo_world() {
  static const World world = load_world(std::string(REFLOC_SOURCE_DIR) + "/deploy/config/world_demo.json");
  return world;
}

void BM_RenderStaticScanDemoHall(benchmark::State& state) {
  ScanRenderConfig config;
  config.sensor.beam_subrays = static_cast<int>(state.range(0));
  ScanRenderer renderer(config);
  std::mt19937_64 rng(1);
  LaserScan scan;
  const Pose2 pose{6.7, 2.2, 0.3};
  for (auto _ : state) {
    renderer.render(demo_world(), pose, 0, rng, scan);
    benchmark::DoNotOptimize(scan.ranges.data());
  }
  state.counters["beams/s"] = benchmark::Counter(541.0 * state.iterations(), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RenderStaticScanDemoHall)->Arg(1)->Arg(5)->Arg(11)->Arg(21)->Unit(benchmark::kMicrosecond);

void BM_RenderStaticScanDemoHallBruteForce(benchmark::State& state) {
  ScanRenderer renderer;
  renderer.set_brute_force(true);
  std::mt19937_64 rng(1);
  LaserScan scan;
  const Pose2 pose{6.7, 2.2, 0.3};
  for (auto _ : state) {
    renderer.render(demo_world(), pose, 0, rng, scan);
    benchmark::DoNotOptimize(scan.ranges.data());
  }
}
BENCHMARK(BM_RenderStaticScanDemoHallBruteForce)->Unit(benchmark::kMicrosecond);

void BM_RenderMovingScanDemoHall(benchmark::State& state) {
  ScanRenderer renderer;
  std::mt19937_64 rng(1);
  LaserScan scan;
  const PoseAtTime moving = [](int64_t utime) {
    const double t = utime * 1e-6;
    return Pose2{2.0 + 1.0 * t, 2.2, 0.3 + 0.5 * t};
  };
  int64_t utime = 0;
  for (auto _ : state) {
    renderer.render(demo_world(), moving, utime, rng, scan);
    utime += 20000;
    benchmark::DoNotOptimize(scan.ranges.data());
  }
}
BENCHMARK(BM_RenderMovingScanDemoHall)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
