#pragma once
// Which scan headers the driver refuses to publish: values no LMS1xx sends, which would turn
// into negative or kilometre ranges, a 100 s scan period or beam times that do not fit into
// one revolution (issue 11), and telegrams of a multi-layer scanner (an MRS sends its layers one
// after another: published as one stream they would interleave). The bounds come from the
// configured device profile (device_profile.hpp); a refused scan is counted per reason and
// never published.

#include "lms100_driver/device_profile.hpp"
#include "lms100_driver/lmd_scandata.hpp"

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

/// DIST1 offset accepted [mm]: every SICK telegram seen sends 0.
inline constexpr float kMaxPlausibleDistOffsetMm = 0.0F;
/// How far a reported scan frequency may be from one of the profile's [Hz].
inline constexpr double kScanFrequencyToleranceHz = 0.5;
/// Angular steps accepted [deg x 1e4]: (0, 1 deg].
inline constexpr uint32_t kMaxPlausibleStep1e4deg = 10000;
/// Raw distances below this are codes, not distances ("valid starting from 16d").
inline constexpr uint16_t kFirstValidDistanceCode = 16;

/// Why a scan was refused; kNone for a plausible one.
enum class ScanImplausibility {
  kNone,
  kLayerAngle,
  kScale,
  kOffset,
  kScanFrequency,
  kBeamCount,
  kAngles,
  kBeamTiming
};

struct ScanPlausibility {
  ScanImplausibility reason = ScanImplausibility::kNone;
  std::string detail;  ///< e.g. "DIST1 scale factor -1 (expected 1 or 2)"; empty when plausible
  explicit operator bool() const { return reason == ScanImplausibility::kNone; }
};

/// Checks the header of a scan that parsed (DIST1 present, frequencies non-zero) against the
/// limits of the device it should come from.
ScanPlausibility check_scan_plausibility(const LmdScanData& data,
                                         const DeviceProfile& device = lms1xx_profile());

/// The HEARTBEAT counter of a reason ("implausible_scale", ...); "" for kNone.
const char* implausibility_counter(ScanImplausibility reason);

/// Beams of DIST1 carrying a reserved code 2..15 (published as "no echo").
size_t count_reserved_distance_codes(const LmdScanData& data);

}  // namespace refloc
