#include "reflector_extractor/energy_filter.hpp"

namespace refloc {

double rssi_8bit(const LaserScan& scan, size_t i) {
  if (scan.rssi_bits == 0 || i >= scan.rssi.size()) return 0.0;
  const double raw = static_cast<double>(scan.rssi[i]);
  // 65535 / 255 = 257 maps full scale onto full scale.
  return scan.rssi_bits == 8 ? raw : raw / 257.0;
}

bool is_echo(const LaserScan& scan, size_t i) {
  const double r = static_cast<double>(scan.ranges[i]);
  return r >= scan.range_min && r <= scan.range_max;
}

void select_high_energy_beams(const LaserScan& scan, double threshold_8bit, std::vector<uint8_t>& high) {
  const size_t n = scan.ranges.size();
  high.assign(n, 0);
  if (scan.rssi_bits == 0 || scan.rssi.size() != n) return;
  for (size_t i = 0; i < n; ++i) {
    high[i] = static_cast<uint8_t>(is_echo(scan, i) && rssi_8bit(scan, i) >= threshold_8bit);
  }
}

}  // namespace refloc
