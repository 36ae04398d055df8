#include "lms100_driver/scan_plausibility.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {
namespace {

ScanPlausibility refuse(ScanImplausibility reason, std::string detail) { return {reason, std::move(detail)}; }

template <class T>

std::string list(const std::vector<T>& values) {
  std::string text;
  for (const T v : values) text += (text.empty() ? "" : ", ") + fmt::format("{}", v);
  return text;
}

}  // namespace

ScanPlausibility check_scan_plausibility(const LmdScanData& data, const DeviceProfile& device) {
  if (data.reserved_layer_angle != 0) {
    return refuse(ScanImplausibility::kLayerAngle,
                  fmt::format("layer angle {} (x 1/10000 deg): a multi-layer scanner (MRS); refloc takes one "
                              "layer, and publishing every layer as one stream would interleave them",
                              static_cast<int16_t>(data.reserved_layer_angle)));
  }
  const LmdChannel* dist = data.find_channel("DIST1");
  if (dist == nullptr) return refuse(ScanImplausibility::kScale, "no DIST1 channel");
  bool scale_ok = false;
  for (const float s : device.dist_scales) scale_ok = scale_ok || dist->scale == s;
  if (!scale_ok)
    return refuse(ScanImplausibility::kScale,
                  fmt::format("DIST1 scale factor {} (expected {} for {})", dist->scale,
                              list(device.dist_scales), device.name));
  if (!(std::fabs(dist->offset) <= kMaxPlausibleDistOffsetMm))
    return refuse(ScanImplausibility::kOffset, fmt::format("DIST1 offset {} mm (expected 0)", dist->offset));

  const double frequency_hz = data.scan_frequency_1e2hz * 0.01;
  bool frequency_ok = false;
  for (const double f : device.scan_frequencies_hz)
    frequency_ok = frequency_ok || std::fabs(frequency_hz - f) <= kScanFrequencyToleranceHz;
  if (!frequency_ok)
    return refuse(ScanImplausibility::kScanFrequency,
                  fmt::format("scan frequency {:.2f} Hz, period {:.3f} s (expected {} Hz for {})",
                              frequency_hz, frequency_hz > 0 ? 1.0 / frequency_hz : 0.0,
                              list(device.scan_frequencies_hz), device.name));

  const size_t n = dist->values.size();
  if (n == 0 || n > device.max_beams)
    return refuse(ScanImplausibility::kBeamCount,
                  fmt::format("{} beams (expected 1..{} for {})", n, device.max_beams, device.name));
  const int64_t first = dist->start_angle_1e4deg;
  const int64_t last = first + static_cast<int64_t>(dist->step_1e4deg) * static_cast<int64_t>(n - 1);
  if (dist->step_1e4deg == 0 || dist->step_1e4deg > kMaxPlausibleStep1e4deg ||
      first < device.min_angle_1e4deg || last > device.max_angle_1e4deg) {
    return refuse(
        ScanImplausibility::kAngles,
        fmt::format("beams from {} to {} deg in steps of {} deg (expected within {}..{} deg for {}, "
                    "step <= 1 deg)",
                    first * 1e-4, last * 1e-4, dist->step_1e4deg * 1e-4, device.min_angle_1e4deg * 1e-4,
                    device.max_angle_1e4deg * 1e-4, device.name));
  }
  // Beams are measured one after another within one revolution: n beams at the beam rate
  // must fit into the scan period.
  const double beam_time_s = 1.0 / (data.measurement_frequency_1e1khz * 100.0);
  const double period_s = 1.0 / frequency_hz;
  if (!(n * beam_time_s <= period_s)) {
    return refuse(ScanImplausibility::kBeamTiming,
                  fmt::format("{} beams x {:.1f} us = {:.1f} ms, longer than the {:.1f} ms scan period", n,
                              beam_time_s * 1e6, n * beam_time_s * 1e3, period_s * 1e3));
  }
  return {};
}

const char* implausibility_counter(ScanImplausibility reason) {
  switch (reason) {
    case ScanImplausibility::kNone:
      return "";
    case ScanImplausibility::kLayerAngle:
      return "multi_layer_scans";
    case ScanImplausibility::kScale:
      return "implausible_scale";
    case ScanImplausibility::kOffset:
      return "implausible_offset";
    case ScanImplausibility::kScanFrequency:
      return "implausible_scan_frequency";
    case ScanImplausibility::kBeamCount:
      return "implausible_beam_count";
    case ScanImplausibility::kAngles:
      return "implausible_angles";
    case ScanImplausibility::kBeamTiming:
      return "implausible_beam_timing";
  }
  return "";
}

size_t count_reserved_distance_codes(const LmdScanData& data) {
  const LmdChannel* dist = data.find_channel("DIST1");
  if (dist == nullptr) return 0;
  size_t n = 0;
  for (const uint16_t raw : dist->values) n += raw >= 2 && raw < kFirstValidDistanceCode;
  return n;
}

}  // namespace refloc
