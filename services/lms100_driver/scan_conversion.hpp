#pragma once
// LmdScanData (sensor units) → refloc::LaserScan (SI, laser frame).

#include "common/laser_scan.hpp"
#include "lms100_driver/lmd_scandata.hpp"
#include "lms100_driver/parse_result.hpp"

namespace refloc {

/// The LMS100's 0 deg points 90 deg to the right of straight ahead (docs/lms100-protocol.md §5.3).
inline constexpr double kLms100AngleShiftDeg = -90.0;

/// Fills ranges, rssi, angles and timing of out from DIST1 (and RSSI1 when present in
/// either block). Leaves the host times (utime, receive_utime) and the unwrapped sensor
/// clock fields to the caller, which owns the clock filter. Reuses out's vectors.
/// Fails when DIST1 is missing, RSSI1's layout differs from DIST1's, or a frequency is 0.
ParseResult to_laser_scan(const LmdScanData& data, LaserScan& out);

}  // namespace refloc
