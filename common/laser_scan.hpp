#pragma once
// A laser scan as plain data: what the driver produces, the renderer simulates
// and the extractor consumes. No LCM here; main.cpp files convert at the edge
// (common/lcm_conversions.hpp).
//
// Laser frame: x forward, y left, angles counter-clockwise. The LMS100's own
// angles (-45..225 deg, 90 deg straight ahead) are shifted by -90 deg, so a
// 270 deg scan spans -135..135 deg here.

#include <cstddef>
#include <cstdint>
#include <vector>

namespace refloc {

struct LaserScan {
  int64_t utime = 0;               ///< host time of the first beam [us]
  int64_t receive_utime = 0;       ///< host time the telegram was complete [us]
  int64_t sensor_start_us = 0;     ///< sensor clock at the first beam, unwrapped [us]
  int64_t sensor_transmit_us = 0;  ///< sensor clock at transmission, unwrapped [us]
  uint32_t scan_counter = 0;
  uint32_t telegram_counter = 0;
  uint32_t device_status = 0;
  uint32_t serial_number = 0;

  double start_angle = 0.0;      ///< angle of beam 0 [rad]
  double angle_increment = 0.0;  ///< [rad]
  double time_increment = 0.0;   ///< time between beams [s]
  double scan_period = 0.0;      ///< time between scans [s]
  double range_min = 0.05;       ///< [m]; smaller ranges are not echoes
  double range_max = 20.0;       ///< [m]

  std::vector<float> ranges;  ///< [m]; 0 = no echo, 0.001 = dazzled (sensor codes 0 and 1)
  std::vector<int32_t> rssi;  ///< as the sensor reports it; empty or ranges.size()
  int rssi_bits = 0;          ///< 8 or 16; 0 without RSSI

  /// Angle of beam i [rad].
  double beam_angle(size_t i) const { return start_angle + static_cast<double>(i) * angle_increment; }
  /// Host time of beam i [us].
  int64_t beam_utime(size_t i) const {
    return utime + static_cast<int64_t>(static_cast<double>(i) * time_increment * 1e6 + 0.5);
  }
};

}  // namespace refloc
