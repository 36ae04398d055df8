// Per-scan cost of the extractor on a 541-beam scan of a 20 m x 12 m hall with 8
// reflectors at 1-5.2 m (synthetic scan: dull walls, 12 mm noise).

#include "reflector_extractor/adaptive_breakpoint.hpp"
#include "reflector_extractor/energy_filter.hpp"
#include "reflector_extractor/extractor.hpp"
#include "reflector_extractor/synthetic_scan.hpp"

#include <benchmark/benchmark.h>

#include <cmath>

namespace refloc {
namespace {

LaserScan hall_scan() {
  SyntheticScene scene;
  for (int k = 0; k < 8; ++k) {
    const double range = 1.0 + 0.6 * k;
    const double bearing = (-120.0 + 32.0 * k) * M_PI / 180.0;
    SyntheticCylinder c;
    c.laser_p_center = {range * std::cos(bearing), range * std::sin(bearing)};
    scene.cylinders.push_back(c);
  }
  const Eigen::Vector2d corners[4] = {{-4.0, -6.0}, {16.0, -6.0}, {16.0, 6.0}, {-4.0, 6.0}};
  for (int k = 0; k < 4; ++k) scene.segments.push_back({corners[k], corners[(k + 1) % 4], 60.0});
  std::mt19937 rng(1);
  return render_synthetic_scan(scene, SyntheticScanConfig{}, rng);
}

void BM_ExtractDefaultMode(benchmark::State& state) {
  const LaserScan scan = hall_scan();
  ReflectorExtractor extractor;
  size_t found = 0;
  for (auto _ : state) {
    found = extractor.extract(scan).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["reflectors"] = static_cast<double>(found);
}
BENCHMARK(BM_ExtractDefaultMode);

void BM_ExtractPaperMode(benchmark::State& state) {
  const LaserScan scan = hall_scan();
  ReflectorExtractor extractor(ExtractorConfig::paper());
  size_t found = 0;
  for (auto _ : state) {
    found = extractor.extract(scan).size();
    benchmark::DoNotOptimize(found);
  }
  state.counters["reflectors"] = static_cast<double>(found);
}
BENCHMARK(BM_ExtractPaperMode);

void BM_EnergyFilterAndClustering(benchmark::State& state) {
  const LaserScan scan = hall_scan();
  AdaptiveBreakpointClusterer clusterer;
  BeamTable table;
  std::vector<uint8_t> high;
  std::vector<BeamCluster> clusters;
  for (auto _ : state) {
    make_beam_table(scan, table);
    select_high_energy_beams(table, 180.0, high);
    clusterer.cluster(table, high, clusters);
    benchmark::DoNotOptimize(clusters.data());
  }
  state.counters["clusters"] = static_cast<double>(clusters.size());
}
BENCHMARK(BM_EnergyFilterAndClustering);

}  // namespace
}  // namespace refloc

BENCHMARK_MAIN();
