#pragma once
// Energy screening (paper §3.2 step 1): retro-reflective foil returns far more
// energy than paint, metal or concrete, so only high-RSSI echoes can be reflectors.

#include "common/laser_scan.hpp"

#include <cstdint>
#include <vector>

namespace refloc {

/// RSSI of beam i on the paper's 8-bit energy scale (16-bit values divided by 257);
/// 0 when the scan carries no RSSI.
double rssi_8bit(const LaserScan& scan, size_t i);

/// True when beam i is a real echo: range inside [range_min, range_max] (0 = no echo and
/// 0.001 = dazzled are not).
bool is_echo(const LaserScan& scan, size_t i);

/// high[i] = 1 for echoes with rssi_8bit >= threshold_8bit, else 0. Reuses high's storage.
/// Without RSSI nothing passes: reflectors cannot be told from other surfaces.
void select_high_energy_beams(const LaserScan& scan, double threshold_8bit, std::vector<uint8_t>& high);

}  // namespace refloc
