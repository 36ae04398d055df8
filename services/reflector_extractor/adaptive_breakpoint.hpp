#pragma once
// Adaptive breakpoint clustering (paper §3.2 step 2, eq. 3; Borges & Aldon 2004):
// two consecutive points belong to one object when they are closer than
//   D_max = r_{i-1} * sin(dphi) / sin(lambda - dphi) + 3 sigma_r,
// the distance the next beam would see on a surface inclined at lambda to the beam,
// so the threshold grows with range instead of being one fixed distance.

#include "reflector_extractor/beam_table.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

struct AdaptiveBreakpointConfig {
  double lambda = 10.0 * 3.14159265358979323846 / 180.0;  ///< auxiliary incidence angle [rad]
  double range_sigma = 0.012;                             ///< range noise sigma_r [m]
  /// Non-selected beams allowed inside a cluster. 0: any unselected beam ends the cluster
  /// (objects side by side at the same range always split); negative: unlimited, the
  /// paper's literal "screen, then cluster the remaining points".
  int max_gap_beams = 0;
};

/// Beams first..last (inclusive) of one cluster; only selected beams belong to it.
struct BeamCluster {
  int first = 0;
  int last = 0;
  int num_selected = 0;
};

class AdaptiveBreakpointClusterer {
 public:
  explicit AdaptiveBreakpointClusterer(AdaptiveBreakpointConfig config = {});

  /// D_max for a previous point at range_prev [m] and angular step dphi [rad] (eq. 3) [m].
  double max_distance(double range_prev, double dphi) const;

  /// Cluster the beams with selected[i] != 0 in beam order; clusters is overwritten
  /// (its storage reused, so the per-scan path does not allocate once warmed up).
  void cluster(const BeamTable& table, const std::vector<uint8_t>& selected,
               std::vector<BeamCluster>& clusters) const;

  const AdaptiveBreakpointConfig& config() const { return config_; }

 private:
  AdaptiveBreakpointConfig config_;
};

}  // namespace refloc
