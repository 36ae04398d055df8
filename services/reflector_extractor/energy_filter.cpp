#include "reflector_extractor/energy_filter.hpp"

namespace refloc {

void select_high_energy_beams(const BeamTable& table, double threshold_8bit, std::vector<uint8_t>& high) {
  const size_t n = table.size();
  high.assign(n, 0);
  if (!table.has_rssi) return;
  for (size_t i = 0; i < n; ++i) {
    high[i] = static_cast<uint8_t>(table.is_echo(i) && table.beams[i].rssi_8bit >= threshold_8bit);
  }
}

}  // namespace refloc
