#pragma once
// Energy screening (paper §3.2 step 1): retro-reflective foil returns far more
// energy than paint, metal or concrete, so only high-RSSI echoes can be reflectors.

#include "reflector_extractor/beam_table.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

/// high[i] = 1 for echoes with rssi_8bit >= threshold_8bit, else 0. Reuses high's storage.
/// Without RSSI nothing passes: reflectors cannot be told from other surfaces.
void select_high_energy_beams(const BeamTable& table, double threshold_8bit, std::vector<uint8_t>& high);

}  // namespace refloc
