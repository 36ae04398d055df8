#pragma once
// The surface a reflector stands in front of, as the spot model's background (EchoSpotModel,
// "the wall behind"): read from the dull echoes beside a cluster of bright beams.

#include "reflector_extractor/adaptive_breakpoint.hpp"
#include "reflector_extractor/beam_table.hpp"
#include "reflector_extractor/circle_fit.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

/// Sets each fit beam's background_range and background_energy_ratio from the dull echo two
/// beams beside each edge of cluster (else one) that lies behind the edge within merge_distance
/// [m]: the line through both sides (one side: its range), its energy the sides' RSSI over the
/// cluster's brightest (beam_rssi, 8-bit scale, one per fit beam; bright: the energy screen).
/// Beams left without: none within reach, or the surface not behind them within merge_distance.
void find_spot_background(const BeamTable& table, const BeamCluster& cluster,
                          const std::vector<uint8_t>& bright, const std::vector<double>& beam_rssi,
                          double merge_distance, std::vector<FitBeam>& beams);

}  // namespace refloc
