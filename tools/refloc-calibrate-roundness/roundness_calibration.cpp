#include "roundness_calibration.hpp"

#include <cmath>

namespace refloc {

std::vector<RoundnessSample> simulate_roundness_samples(const PlacementGrid& grid, int drop_points,
                                                        const ReflectorScanRenderer& render) {
  ExtractorConfig config = ExtractorConfig::paper();
  config.paper_drop_points = drop_points;
  // Measure d-bar, do not judge it: the line is what is being calibrated.
  config.paper_roundness.offset = 1e9;
  config.paper_roundness.slope = 0.0;
  ReflectorExtractor extractor(config);
  std::vector<RoundnessSample> samples;
  LaserScan scan;
  const int distances =
      static_cast<int>(std::floor((grid.distance_max - grid.distance_min) / grid.distance_step + 1e-9)) + 1;
  const int angles =
      static_cast<int>(std::floor((grid.angle_max - grid.angle_min) / grid.angle_step + 1e-9)) + 1;
  for (int i = 0; i < distances; ++i) {
    const double distance = grid.distance_min + i * grid.distance_step;
    for (int j = 0; j < angles; ++j) {
      const double angle = grid.angle_min + j * grid.angle_step;
      for (int k = 0; k < grid.scans_per_placement; ++k) {
        render(distance, angle, scan);
        const std::vector<ReflectorDetection>& detections = extractor.extract(scan);
        // The placement's reflector is the detection nearest its true position.
        const ReflectorDetection* best = nullptr;
        double best_error = 0.5;
        const double x = distance * std::cos(angle);
        const double y = distance * std::sin(angle);
        for (const ReflectorDetection& d : detections) {
          const double error = std::hypot(d.laser_p_center.x() - x, d.laser_p_center.y() - y);
          if (error < best_error) {
            best = &d;
            best_error = error;
          }
        }
        if (best != nullptr) samples.push_back({distance, angle, best->roundness_m});
      }
    }
  }
  return samples;
}

RoundnessLineFit fit_roundness_line(const std::vector<RoundnessSample>& samples, double fit_min,
                                    double fit_max, double raise) {
  RoundnessLineFit out;
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const RoundnessSample& s : samples) {
    if (s.distance < fit_min || s.distance > fit_max) continue;
    n += 1.0;
    sx += s.distance;
    sy += s.d_bar;
    sxx += s.distance * s.distance;
    sxy += s.distance * s.d_bar;
  }
  const double denominator = n * sxx - sx * sx;
  if (n < 2.0 || std::abs(denominator) < 1e-12) return out;
  const double slope = (n * sxy - sx * sy) / denominator;
  const double offset = (sy - slope * sx) / n;
  double sum_sq = 0.0;
  for (const RoundnessSample& s : samples) {
    if (s.distance < fit_min || s.distance > fit_max) continue;
    const double e = s.d_bar - (offset + slope * s.distance);
    sum_sq += e * e;
  }
  out.line.offset = offset + raise;
  out.line.slope = slope;
  out.samples_used = static_cast<int>(n);
  out.residual_rms = std::sqrt(sum_sq / n);
  return out;
}

}  // namespace refloc
