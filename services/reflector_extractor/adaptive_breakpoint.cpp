#include "reflector_extractor/adaptive_breakpoint.hpp"

#include <cmath>
#include <limits>

namespace refloc {

AdaptiveBreakpointClusterer::AdaptiveBreakpointClusterer(AdaptiveBreakpointConfig config) : config_(config) {}

double AdaptiveBreakpointClusterer::max_distance(double range_prev, double dphi) const {
  const double denominator = std::sin(config_.lambda - dphi);
  // lambda <= dphi would mean every surface is "too inclined": nothing may join.
  if (denominator <= 0.0) return 3.0 * config_.range_sigma;
  return range_prev * std::sin(dphi) / denominator + 3.0 * config_.range_sigma;
}

void AdaptiveBreakpointClusterer::cluster(const BeamTable& table, const std::vector<uint8_t>& selected,
                                          std::vector<BeamCluster>& clusters) const {
  clusters.clear();
  const int n = static_cast<int>(std::min(table.size(), selected.size()));
  const double dphi = std::abs(table.angle_increment);
  const int max_gap = config_.max_gap_beams < 0 ? std::numeric_limits<int>::max() : config_.max_gap_beams;
  int prev = -1;
  double prev_x = 0.0;
  double prev_y = 0.0;
  double prev_r = 0.0;
  for (int i = 0; i < n; ++i) {
    if (selected[static_cast<size_t>(i)] == 0) continue;
    const TableBeam& beam = table.beams[static_cast<size_t>(i)];
    const double r = beam.range;
    const double x = beam.point.x();
    const double y = beam.point.y();
    bool joins = false;
    if (prev >= 0 && i - prev - 1 <= max_gap) {
      joins = std::hypot(x - prev_x, y - prev_y) <= max_distance(prev_r, dphi);
    }
    if (joins) {
      clusters.back().last = i;
      ++clusters.back().num_selected;
    } else {
      clusters.push_back(BeamCluster{i, i, 1});
    }
    prev = i;
    prev_x = x;
    prev_y = y;
    prev_r = r;
  }
}

}  // namespace refloc
