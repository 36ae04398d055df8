#include "reflector_extractor/spot_background.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {

void find_spot_background(const BeamTable& table, const BeamCluster& cluster,
                          const std::vector<uint8_t>& bright, const std::vector<double>& beam_rssi,
                          double merge_distance, std::vector<FitBeam>& beams) {
  // The dull echo two beams beside each edge (one beam beside, a far beam's spot still grazes the
  // cylinder), else one: the surface the reflector stands in front of, when it lies behind the
  // edge within the merge distance.
  const double merge = merge_distance;
  const int n = static_cast<int>(table.size());
  const TableBeam* sides[2] = {nullptr, nullptr};
  const int edges[2] = {cluster.first, cluster.last};
  for (int side = 0; side < 2; ++side) {
    const int step = side == 0 ? -1 : 1;
    const double edge_range = table.beams[static_cast<size_t>(edges[side])].range;
    for (const int distance : {2, 1}) {
      const int j = edges[side] + step * distance;
      if (j < 0 || j >= n) continue;
      const TableBeam& t = table.beams[static_cast<size_t>(j)];
      if (t.kind != BeamKind::kEcho || bright[static_cast<size_t>(j)] != 0) continue;
      if (t.range > edge_range && t.range - edge_range <= merge) {
        sides[side] = &t;
        break;
      }
    }
  }
  if (sides[0] == nullptr && sides[1] == nullptr) return;
  const double brightest = *std::max_element(beam_rssi.begin(), beam_rssi.end());
  if (!(brightest > 0.0)) return;
  double rssi = 0.0;
  int count = 0;
  for (const TableBeam* t : sides) {
    if (t == nullptr) continue;
    rssi += t->rssi_8bit;
    ++count;
  }
  const double ratio = std::clamp(rssi / count / brightest, 0.0, 1.0);
  for (FitBeam& b : beams) {
    double range = std::numeric_limits<double>::quiet_NaN();
    if (sides[0] != nullptr && sides[1] != nullptr) {
      // The surface as the line through the two: where this beam meets it.
      const Eigen::Vector2d along_surface = sides[1]->point - sides[0]->point;
      const double denominator = b.direction.x() * along_surface.y() - b.direction.y() * along_surface.x();
      if (std::abs(denominator) > 1e-9)
        range =
            (sides[0]->point.x() * along_surface.y() - sides[0]->point.y() * along_surface.x()) / denominator;
    } else {
      range = (sides[0] != nullptr ? sides[0] : sides[1])->range;
    }
    if (range > b.range && range - b.range <= merge) {
      b.background_range = range;
      b.background_energy_ratio = ratio;
    }
  }
}

}  // namespace refloc
