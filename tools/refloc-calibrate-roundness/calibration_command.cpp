#include "calibration_command.hpp"

#include "common/json_config.hpp"
#include "common/lcm_bounded_decode.hpp"
#include "reflector_extractor/synthetic_scan.hpp"
#include "roundness_calibration.hpp"

#ifdef REFLOC_HAVE_WORLD_RENDERER
#include "world_renderer/scan_renderer.hpp"
#endif

#include <fmt/core.h>
#include <lcm/lcm-cpp.hpp>
#include <refloc/reflector_detections_t.hpp>

#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <string>

namespace refloc {
namespace {

std::vector<RoundnessSample> samples_from_log(const CalibrationOptions& o) {
  lcm::LogFile log(o.log_path, "r");
  if (!log.good()) throw ConfigError(o.log_path + ": cannot open as an LCM log");
  std::vector<RoundnessSample> samples;
  int decode_errors = 0;
  for (const lcm::LogEvent* event = log.readNextEvent(); event != nullptr; event = log.readNextEvent()) {
    if (event->channel != o.channel) continue;
    reflector_detections_t msg;
    if (!decode_lcm_bounded(event->data, static_cast<size_t>(event->datalen), msg).ok) {
      ++decode_errors;
      continue;
    }
    for (const reflector_t& r : msg.reflectors) samples.push_back({r.range, r.bearing, r.roundness_m});
  }
  if (decode_errors > 0)
    fmt::print(stderr, "{}: {} messages on {} did not decode\n", o.log_path, decode_errors, o.channel);
  return samples;
}

ReflectorScanRenderer make_renderer(const CalibrationOptions& o, std::mt19937_64& rng) {
  if (o.renderer == "synthetic") {
    SyntheticScanConfig config;
    config.range_sigma = o.range_sigma;
    return [config, &rng](double distance, double angle, LaserScan& scan) {
      SyntheticScene scene;
      SyntheticCylinder c;
      c.laser_p_center = {distance * std::cos(angle), distance * std::sin(angle)};
      scene.cylinders.push_back(c);
      const Eigen::Vector2d along(-std::sin(angle), std::cos(angle));
      const Eigen::Vector2d wall = (distance + 1.0) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
      scene.segments.push_back({wall - 2.0 * along, wall + 2.0 * along, 60.0});
      std::mt19937 local(static_cast<uint32_t>(rng()));
      scan = render_synthetic_scan(scene, config, local);
    };
  }
#ifdef REFLOC_HAVE_WORLD_RENDERER
  auto renderer = std::make_shared<sim::ScanRenderer>();
  return [renderer, &rng](double distance, double angle, LaserScan& scan) {
    sim::World world;
    MapReflector reflector;
    reflector.id = 1;
    reflector.map_p_center = {distance * std::cos(angle), distance * std::sin(angle)};
    world.reflectors.reflectors.push_back(reflector);
    const Eigen::Vector2d along(-std::sin(angle), std::cos(angle));
    const Eigen::Vector2d wall = (distance + 1.0) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    world.segments.push_back({wall - 2.0 * along, wall + 2.0 * along, sim::SurfaceKind::kDiffuse, 0.5});
    renderer->render(world, Pose2{}, 1'000'000, rng, scan);
  };
#else
  throw ConfigError("--renderer emulator: built without services/lms100_emulator; use --renderer synthetic");
#endif
}

}  // namespace

int run_calibration(const CalibrationOptions& o) {
  std::vector<RoundnessSample> samples;
  if (!o.log_path.empty()) {
    samples = samples_from_log(o);
    fmt::print(
        "{}: {} detections on {} (d-bar = their roundness_m; paper-mode logs give the paper's index)\n",
        o.log_path, samples.size(), o.channel);
  } else {
    PlacementGrid grid;
    grid.distance_max = o.distance_max;
    grid.scans_per_placement = o.scans;
    std::mt19937_64 rng(o.seed);
    samples = simulate_roundness_samples(grid, o.drop_points, make_renderer(o, rng));
    fmt::print(
        "simulated ({} renderer): {} samples from placements {:.2f}..{:.2f} m x {:.0f}..{:.0f} deg, "
        "{} scan(s) each, first and last {} point(s) dropped\n",
        o.renderer, samples.size(), grid.distance_min, grid.distance_max, grid.angle_min * 180.0 / M_PI,
        grid.angle_max * 180.0 / M_PI, grid.scans_per_placement, o.drop_points);
  }
  if (!o.csv_path.empty()) {
    std::ofstream csv(o.csv_path);
    csv << "distance_m,angle_deg,d_bar_m\n";
    for (const RoundnessSample& s : samples)
      csv << fmt::format("{:.4f},{:.2f},{:.6f}\n", s.distance, s.angle * 180.0 / M_PI, s.d_bar);
  }
  // The per-distance table of Figure 9 (bins of 0.25 m).
  std::map<int, std::vector<double>> by_distance;
  for (const RoundnessSample& s : samples)
    by_distance[static_cast<int>(std::lround(s.distance / 0.25))].push_back(s.d_bar);
  fmt::print("{:>10} {:>6} {:>12} {:>12}\n", "distance_m", "n", "mean_dbar_mm", "max_dbar_mm");
  for (const auto& [bin, values] : by_distance) {
    double sum = 0.0, max = 0.0;
    for (double v : values) {
      sum += v;
      max = std::max(max, v);
    }
    fmt::print("{:>10.2f} {:>6} {:>12.2f} {:>12.2f}\n", bin * 0.25, values.size(), 1e3 * sum / values.size(),
               1e3 * max);
  }
  const RoundnessLineFit fit = fit_roundness_line(samples, o.fit_min, o.fit_max, o.raise_mm * 1e-3);
  if (fit.samples_used == 0) throw std::runtime_error("not enough samples in the fit range to fit a line");
  const double fitted_offset = fit.line.offset - o.raise_mm * 1e-3;
  int under = 0;
  for (const RoundnessSample& s : samples) under += fit.line.accepts(s.d_bar, s.distance) ? 1 : 0;
  fmt::print(
      "fitted line over {:.2f}..{:.2f} m ({} samples, rms {:.2f} mm): d_bar = {:.2f} mm + {:.3f} mm/m * "
      "distance\n",
      o.fit_min, o.fit_max, fit.samples_used, 1e3 * fit.residual_rms, 1e3 * fitted_offset,
      1e3 * fit.line.slope);
  fmt::print("raised by {:.0f} mm: d_bar <= {:.2f} mm + {:.3f} mm/m * distance ({} of {} samples under it)\n",
             o.raise_mm, 1e3 * fit.line.offset, 1e3 * fit.line.slope, under, samples.size());
  fmt::print(
      "config (deploy/config/reflector_extractor.json): \"paper\": {{\"roundness_offset_m\": {:.4f}, "
      "\"roundness_slope\": {:.5f}}}\n",
      fit.line.offset, fit.line.slope);
  return 0;
}

}  // namespace refloc
