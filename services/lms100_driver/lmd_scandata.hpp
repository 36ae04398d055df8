#pragma once
// The LMDscandata telegram (sRA reply to a poll, sSN stream event) decoded
// field by field, in the units the sensor sends (docs/lms100-protocol.md §5.1).
// Conversion to SI and to the laser frame is scan_conversion.hpp's job.

#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

/// One measurement channel (DIST1, DIST2, RSSI1, ...) of the 16- or 8-bit block.
struct LmdChannel {
  std::string name;    ///< 5 characters, e.g. "DIST1", "RSSI1"
  float scale = 1.0F;  ///< raw * scale + offset
  float offset = 0.0F;
  int32_t start_angle_1e4deg = 0;  ///< sensor angle of value 0 [deg x 1e4]
  uint32_t step_1e4deg = 0;        ///< [deg x 1e4]
  std::vector<uint16_t> values;    ///< sized from the telegram's own count field
};

struct LmdEncoder {
  uint32_t position_ticks = 0;
  uint32_t speed_ticks_per_mm = 0;
};

/// Position block (LMS5xx manual layout; all drivers keep it off).
struct LmdPosition {
  float x = 0, y = 0, z = 0;  ///< as sent (device units)
  float x_rotation = 0, y_rotation = 0, z_rotation = 0;
  uint32_t rotation_type = 0;
  uint32_t transmits_name = 0;
};

/// The device's real-time clock at the scan (not the microsecond counter).
struct LmdTimeInfo {
  uint32_t year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0;
  uint32_t microsecond = 0;
};

/// Event block (LMS5xx manual layout; LMS1xx sends 0).
struct LmdEvent {
  std::string type;  ///< e.g. "FDIN"
  uint32_t encoder_position = 0;
  uint32_t time_us = 0;
  int32_t angle_1e4deg = 0;
};

struct LmdScanData {
  bool is_stream_event = false;  ///< sSN (stream) rather than sRA (poll reply)
  uint32_t version = 0;
  uint32_t device_number = 0;
  uint32_t serial_number = 0;
  uint32_t device_status[2] = {0, 0};  ///< "0 0" = OK
  uint32_t telegram_counter = 0;       ///< uint16, wraps
  uint32_t scan_counter = 0;           ///< uint16, wraps
  uint32_t time_since_startup_us = 0;  ///< sensor clock at the zero index, wraps every 71.6 min
  uint32_t time_of_transmission_us = 0;
  uint32_t digital_inputs[2] = {0, 0};
  uint32_t digital_outputs[2] = {0, 0};
  uint32_t reserved_layer_angle = 0;          ///< 0 on LMS1xx
  uint32_t scan_frequency_1e2hz = 0;          ///< 5000 = 50 Hz
  uint32_t measurement_frequency_1e1khz = 0;  ///< beam rate [kHz x 10] (360 = 36 kHz)
  std::vector<LmdEncoder> encoders;
  std::vector<LmdChannel> channels16;
  std::vector<LmdChannel> channels8;
  bool has_position = false;
  LmdPosition position;
  bool has_name = false;
  std::string name;  ///< may contain spaces
  bool has_comment = false;
  std::string comment;
  bool has_time_info = false;
  LmdTimeInfo time_info;
  bool has_event = false;
  LmdEvent event;

  /// The channel called name in the 16-bit block, then the 8-bit block; nullptr if absent.
  const LmdChannel* find_channel(const char* channel_name, int* bits = nullptr) const;
};

}  // namespace refloc
