#pragma once
// The contract between the LMS100 emulator and whatever produces its measurements.
//
// For every scan the emulator sends (stream or poll) it calls the ScanSource once
// with a ScanRequest that says exactly which beams to produce and when each beam
// is "measured". The source fills dist_mm and rssi with num_beams values each.
//
// Who plugs in what:
//  - services/robot_sim plugs the scan renderer with the robot's true, moving pose:
//    beam i is measured at first_beam_utime + i * time_increment_s (motion during
//    the 15 ms sweep is part of what the localization must cope with).
//  - tests plug a deterministic pattern (test_pattern_scan_source.hpp).
//
// Rules for a source:
//  - dist_mm and rssi arrive already sized to num_beams (and zero-filled); write
//    every element. Do not resize them: the emulator reuses the buffers.
//  - dist_mm uses the sensor's codes: 0 = no echo, 1 = dazzled, >= 16 a range [mm].
//  - rssi is 0..65535 when rssi_bits == 16 and 0..255 when rssi_bits == 8 (the
//    emulator clamps to 255 in 8-bit mode); with rssi_bits == 0 it is not sent,
//    so a source may leave it at zero.
//  - It is called from the emulator's server thread, once per scan period at most
//    (50 Hz), and must return well within a scan period. It must not throw.

#include <cstdint>
#include <functional>
#include <vector>

namespace refloc {

/// Which beams the emulator needs for one scan, and when they are measured.
struct ScanRequest {
  int64_t first_beam_utime = 0;             ///< host wall-clock time of beam 0 [us since epoch]
  uint64_t first_beam_sensor_us = 0;        ///< device clock at beam 0, unwrapped [us since power-up]
  double time_increment_s = 1.0 / 36000.0;  ///< time between beams [s] (36 kHz on an LMS1xx)
  int num_beams = 0;
  /// Angle of beam 0 in the laser frame [rad] (x forward, counter-clockwise; the
  /// sensor's -45 deg is -135 deg here, as in common/laser_scan.hpp).
  double start_angle_rad = 0.0;
  double angle_increment_rad = 0.0;  ///< [rad]
  uint32_t scan_counter = 0;         ///< the scan counter this scan will carry (uint16 on the wire)
  int rssi_bits = 16;                ///< 16, 8, or 0 when RSSI output is off
};

/// Fills num_beams distances [mm, sensor codes] and RSSI values for one scan.
using ScanSource = std::function<void(const ScanRequest& request, std::vector<uint16_t>& dist_mm,
                                      std::vector<uint16_t>& rssi)>;

}  // namespace refloc
