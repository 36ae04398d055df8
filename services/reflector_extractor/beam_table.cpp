#include "reflector_extractor/beam_table.hpp"

#include <cmath>

namespace refloc {

double rssi_to_8bit(int32_t raw, int rssi_bits, RssiScale scale) {
  const double value = static_cast<double>(raw);
  return rssi_bits == 8 || scale == RssiScale::k8bitIn16bit ? value : value / 257.0;
}

double rssi_from_8bit(double energy_8bit, int rssi_bits, RssiScale scale) {
  return rssi_bits == 8 || scale == RssiScale::k8bitIn16bit ? energy_8bit : energy_8bit * 257.0;
}

void make_beam_table(const LaserScan& scan, BeamTable& table, RssiScale scale) {
  const size_t n = scan.ranges.size();
  // Beam directions change only with the scan geometry: the trigonometry is skipped otherwise.
  const bool same_geometry = table.beams.size() == n && table.start_angle == scan.start_angle &&
                             table.angle_increment == scan.angle_increment;
  table.beams.resize(n);
  table.has_rssi = scan.rssi_bits != 0 && scan.rssi.size() == n;
  table.start_angle = scan.start_angle;
  table.angle_increment = scan.angle_increment;
  table.utime = scan.utime;
  table.time_increment = scan.time_increment;
  for (size_t i = 0; i < n; ++i) {
    TableBeam& b = table.beams[i];
    b.range = static_cast<double>(scan.ranges[i]);
    if (b.range >= scan.range_min && b.range <= scan.range_max) {
      b.kind = BeamKind::kEcho;
    } else if (b.range > 0.0 && b.range < scan.range_min) {
      b.kind = BeamKind::kDazzled;
    } else {
      b.kind = BeamKind::kNoEcho;
    }
    if (!same_geometry) {
      const double angle = scan.beam_angle(i);
      b.direction = Eigen::Vector2d(std::cos(angle), std::sin(angle));
    }
    b.point = b.range * b.direction;
    b.rssi_8bit = table.has_rssi ? rssi_to_8bit(scan.rssi[i], scan.rssi_bits, scale) : 0.0;
  }
}

}  // namespace refloc
