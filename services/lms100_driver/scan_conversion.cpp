#include "lms100_driver/scan_conversion.hpp"

#include "common/angles.hpp"
#include "lms100_driver/scan_plausibility.hpp"

#include <cmath>
#include <string>

namespace refloc {

namespace {
constexpr uint16_t kDazzledCode = 1;
constexpr float kDazzledRange = 0.001F;  // laser_scan.hpp's marker for code 1
}  // namespace

ParseResult to_laser_scan(const LmdScanData& data, LaserScan& out) {
  const LmdChannel* dist = data.find_channel("DIST1");
  if (dist == nullptr) return ParseResult::failure("LMDscandata has no DIST1 channel");
  if (dist->step_1e4deg == 0) return ParseResult::failure("DIST1 angular step is 0");
  if (data.scan_frequency_1e2hz == 0) return ParseResult::failure("scan frequency is 0");
  if (data.measurement_frequency_1e1khz == 0) return ParseResult::failure("measurement frequency is 0");
  // Corrupt factors must not turn into inf/NaN ranges or out-of-range integer casts.
  const auto sane = [](const LmdChannel& c) {
    return std::isfinite(c.scale) && std::isfinite(c.offset) && std::fabs(c.scale) <= 1e4F &&
           std::fabs(c.offset) <= 1e6F;
  };
  if (!sane(*dist)) return ParseResult::failure("DIST1 scale factor or offset is not plausible");
  int rssi_bits = 0;
  const LmdChannel* rssi = data.find_channel("RSSI1", &rssi_bits);
  if (rssi != nullptr &&
      (rssi->values.size() != dist->values.size() || rssi->start_angle_1e4deg != dist->start_angle_1e4deg ||
       rssi->step_1e4deg != dist->step_1e4deg)) {
    return ParseResult::failure("RSSI1 layout (" + std::to_string(rssi->values.size()) +
                                " values) differs from DIST1 (" + std::to_string(dist->values.size()) + ")");
  }
  if (rssi != nullptr && !sane(*rssi))
    return ParseResult::failure("RSSI1 scale factor or offset is not plausible");

  out.scan_counter = data.scan_counter;
  out.telegram_counter = data.telegram_counter;
  out.device_status = (data.device_status[0] << 8) | data.device_status[1];
  out.serial_number = data.serial_number;
  out.start_angle = (dist->start_angle_1e4deg * 1e-4 + kLms100AngleShiftDeg) * kDegToRad;
  out.angle_increment = dist->step_1e4deg * 1e-4 * kDegToRad;
  out.time_increment = 1.0 / (data.measurement_frequency_1e1khz * 100.0);
  out.scan_period = 100.0 / data.scan_frequency_1e2hz;

  const size_t n = dist->values.size();
  out.ranges.resize(n);
  const double scale_m = dist->scale * 1e-3;
  const double offset_m = dist->offset * 1e-3;
  for (size_t i = 0; i < n; ++i) {
    const uint16_t raw = dist->values[i];
    // One rule for every code below 16 ("distance values are only valid starting from 16d"):
    // 1 is dazzled, 0 and the reserved 2..15 are no echo, never a 2..15 mm range.
    if (raw == kDazzledCode) {
      out.ranges[i] = kDazzledRange;
    } else if (raw < kFirstValidDistanceCode) {
      out.ranges[i] = 0.0F;
    } else {
      out.ranges[i] = static_cast<float>(raw * scale_m + offset_m);
    }
  }
  if (rssi != nullptr) {
    out.rssi.resize(n);
    for (size_t i = 0; i < n; ++i) {
      out.rssi[i] = static_cast<int32_t>(std::lround(rssi->values[i] * rssi->scale + rssi->offset));
    }
    out.rssi_bits = rssi_bits;
  } else {
    out.rssi.clear();
    out.rssi_bits = 0;
  }
  return ParseResult::success();
}

}  // namespace refloc
