#pragma once
// A deterministic scan for tests and for running the emulator without a world:
// a smooth wall profile with a few strong-RSSI "reflector" patches, identical for
// every scan with the same beam angles, so a test can predict every value.

#include "lms100_emulator/scan_source.hpp"

namespace refloc {

/// Range of the test pattern at laser-frame angle [rad] [mm, >= 500].
uint16_t test_pattern_range_mm(double angle_rad);
/// RSSI of the test pattern at laser-frame angle [rad] for 16- or 8-bit output.
uint16_t test_pattern_rssi(double angle_rad, int rssi_bits);
/// A ScanSource that fills every beam from the two functions above.
ScanSource make_test_pattern_scan_source();

}  // namespace refloc
