#include "lms100_driver/scan_plausibility.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {
namespace {

ScanPlausibility refuse(ScanImplausibility reason, std::string detail) { return {reason, std::move(detail)}; }

}  // namespace

ScanPlausibility check_scan_plausibility(const LmdScanData& data) {
  const LmdChannel* dist = data.find_channel("DIST1");
  if (dist == nullptr) return refuse(ScanImplausibility::kScale, "no DIST1 channel");
  bool scale_ok = false;
  for (const float s : kPlausibleDistScales) scale_ok = scale_ok || dist->scale == s;
  if (!scale_ok)
    return refuse(ScanImplausibility::kScale,
                  fmt::format("DIST1 scale factor {} (expected 1 or 2)", dist->scale));
  if (!(std::fabs(dist->offset) <= kMaxPlausibleDistOffsetMm))
    return refuse(ScanImplausibility::kOffset, fmt::format("DIST1 offset {} mm (expected 0)", dist->offset));

  const double frequency_hz = data.scan_frequency_1e2hz * 0.01;
  bool frequency_ok = false;
  for (const double f : kPlausibleScanFrequenciesHz)
    frequency_ok = frequency_ok || std::fabs(frequency_hz - f) <= kScanFrequencyToleranceHz;
  if (!frequency_ok)
    return refuse(ScanImplausibility::kScanFrequency,
                  fmt::format("scan frequency {:.2f} Hz, period {:.3f} s (expected 25 or 50 Hz)",
                              frequency_hz, frequency_hz > 0 ? 1.0 / frequency_hz : 0.0));

  const size_t n = dist->values.size();
  if (n == 0 || n > kMaxPlausibleBeams)
    return refuse(ScanImplausibility::kBeamCount,
                  fmt::format("{} beams (expected 1..{})", n, kMaxPlausibleBeams));
  const int64_t first = dist->start_angle_1e4deg;
  const int64_t last = first + static_cast<int64_t>(dist->step_1e4deg) * static_cast<int64_t>(n - 1);
  if (dist->step_1e4deg == 0 || dist->step_1e4deg > kMaxPlausibleStep1e4deg ||
      first < kMinPlausibleAngle1e4deg || last > kMaxPlausibleAngle1e4deg) {
    return refuse(ScanImplausibility::kAngles,
                  fmt::format("beams from {} to {} deg in steps of {} deg (expected within -47.5..237.5 deg, "
                              "step <= 1 deg)",
                              first * 1e-4, last * 1e-4, dist->step_1e4deg * 1e-4));
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
