#pragma once
// Which scan headers the driver refuses to publish: values no LMS1xx sends, which would turn
// into negative or kilometre ranges, a 100 s scan period or beam times that do not fit into
// one revolution (issue 11). The bounds are the LMS1xx's own (LMS100_PROTOCOL.md §3.3) with
// the margins stated here; a refused scan is counted per reason and never published.

#include "lms100_driver/lmd_scandata.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

/// DIST1 scale factors accepted [mm per raw unit]: the LMS1xx sends 1.0, LMS5xx can send 2.0.
inline constexpr float kPlausibleDistScales[] = {1.0F, 2.0F};
/// DIST1 offset accepted [mm]: every LMS1xx telegram seen sends 0.
inline constexpr float kMaxPlausibleDistOffsetMm = 0.0F;
/// Scan frequencies [Hz] and how far a reported one may be from them [Hz].
inline constexpr double kPlausibleScanFrequenciesHz[] = {25.0, 50.0};
inline constexpr double kScanFrequencyToleranceHz = 0.5;
/// At most this many beams: 285 deg at 0.25 deg (the LMS1xx outputs at most 270 deg).
inline constexpr size_t kMaxPlausibleBeams = 1141;
/// Every beam's sensor angle lies in this field [deg x 1e4]: the 270 deg field -45..225 deg,
/// widened by 2.5 deg on each side (1141 beams at 0.25 deg).
inline constexpr int64_t kMinPlausibleAngle1e4deg = -475000;
inline constexpr int64_t kMaxPlausibleAngle1e4deg = 2375000;
/// Angular steps accepted [deg x 1e4]: (0, 1 deg].
inline constexpr uint32_t kMaxPlausibleStep1e4deg = 10000;
/// Raw distances below this are codes, not distances ("valid starting from 16d").
inline constexpr uint16_t kFirstValidDistanceCode = 16;

/// Why a scan was refused; kNone for a plausible one.
enum class ScanImplausibility { kNone, kScale, kOffset, kScanFrequency, kBeamCount, kAngles, kBeamTiming };

struct ScanPlausibility {
  ScanImplausibility reason = ScanImplausibility::kNone;
  std::string detail;  ///< e.g. "DIST1 scale factor -1 (expected 1 or 2)"; empty when plausible
  explicit operator bool() const { return reason == ScanImplausibility::kNone; }
};

/// Checks the header of a scan that parsed (DIST1 present, frequencies non-zero).
ScanPlausibility check_scan_plausibility(const LmdScanData& data);

/// The HEARTBEAT counter of a reason ("implausible_scale", ...); "" for kNone.
const char* implausibility_counter(ScanImplausibility reason);

/// Beams of DIST1 carrying a reserved code 2..15 (published as "no echo").
size_t count_reserved_distance_codes(const LmdScanData& data);

}  // namespace refloc
