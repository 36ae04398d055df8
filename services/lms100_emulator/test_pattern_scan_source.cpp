#include "lms100_emulator/test_pattern_scan_source.hpp"

#include <cmath>

namespace refloc {

namespace {
/// True on the narrow angular patches where the pattern puts a "reflector".
bool on_reflector_patch(double angle_rad) {
  const double phase = std::fmod(std::fabs(angle_rad) + 0.0001, 0.5);
  return phase < 0.02;
}
}  // namespace

uint16_t test_pattern_range_mm(double angle_rad) {
  return static_cast<uint16_t>(std::lround(3000.0 + 1500.0 * std::sin(3.0 * angle_rad)));
}

uint16_t test_pattern_rssi(double angle_rad, int rssi_bits) {
  if (rssi_bits == 8) return on_reflector_patch(angle_rad) ? 254 : 120;
  return on_reflector_patch(angle_rad) ? 65000 : 20000;
}

ScanSource make_test_pattern_scan_source() {
  return [](const ScanRequest& request, std::vector<uint16_t>& dist_mm, std::vector<uint16_t>& rssi) {
    for (int i = 0; i < request.num_beams; ++i) {
      const double angle = request.start_angle_rad + i * request.angle_increment_rad;
      dist_mm[static_cast<size_t>(i)] = test_pattern_range_mm(angle);
      rssi[static_cast<size_t>(i)] = test_pattern_rssi(angle, request.rssi_bits);
    }
  };
}

}  // namespace refloc
