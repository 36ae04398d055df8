#pragma once
// The paper's roundness calibration (§3.3-3.4): reflectors placed at known distances
// and angles, the roundness index d-bar of each detection, a straight line fitted to
// d-bar against distance over the reliable range, raised by a margin (30 mm in the
// paper) to become the acceptance line of paper mode.

#include "common/laser_scan.hpp"
#include "reflector_extractor/extractor.hpp"

#include <functional>
#include <vector>

namespace refloc {

/// One placement's outcome.
struct RoundnessSample {
  double distance = 0.0;  ///< placement (or measured) distance of the reflector [m]
  double angle = 0.0;     ///< placement angle [rad]
  double d_bar = 0.0;     ///< roundness index [m]
};

/// d_bar = offset + slope * distance.
struct RoundnessLineFit {
  RoundnessLine line;
  int samples_used = 0;
  double residual_rms = 0.0;  ///< of d_bar about the line [m]
};

struct PlacementGrid {
  double distance_min = 0.25;                                  ///< [m]
  double distance_max = 3.0;                                   ///< [m]
  double distance_step = 0.25;                                 ///< [m] (paper: 250 mm)
  double angle_min = -110.0 * 3.14159265358979323846 / 180.0;  ///< [rad]
  double angle_max = 110.0 * 3.14159265358979323846 / 180.0;   ///< [rad]
  double angle_step = 10.0 * 3.14159265358979323846 / 180.0;   ///< [rad]; 12 x 23 = 276 sets
  int scans_per_placement = 1;
};

/// Renders a scan of one reflector whose centre is at (distance, angle) in the laser frame.
using ReflectorScanRenderer = std::function<void(double distance, double angle, LaserScan& scan)>;

/// Run the paper's extraction (energy, clustering, centre fit, d-bar with drop_points,
/// no acceptance line) on every placement; placements without a cluster give no sample.
std::vector<RoundnessSample> simulate_roundness_samples(const PlacementGrid& grid, int drop_points,
                                                        const ReflectorScanRenderer& render);

/// Least-squares line through the samples with distance in [fit_min, fit_max], raised by
/// raise [m]. samples_used = 0 when fewer than 2 samples (or all at one distance) qualify.
RoundnessLineFit fit_roundness_line(const std::vector<RoundnessSample>& samples, double fit_min,
                                    double fit_max, double raise);

}  // namespace refloc
