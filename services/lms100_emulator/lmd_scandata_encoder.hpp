#pragma once
// Writes the LMDscandata telegram (sSN stream event or sRA poll reply) exactly as
// an LMS1xx does in CoLa-A (docs/lms100-protocol.md §5.1, checked against the real
// LMS111 telegram in tests/data/sick-real/lms111_cola_a_scan.txt).

#include <cstddef>
#include <cstdint>
#include <string>

namespace refloc {

/// The device's real-time clock as the telegram's time-info block carries it.
struct LmdCalendarTime {
  uint32_t year = 1970, month = 1, day = 1, hour = 0, minute = 0, second = 0;
  uint32_t microsecond = 0;
};

/// Calendar time (UTC) of a count of microseconds since 1970-01-01.
LmdCalendarTime calendar_time_from_epoch_us(uint64_t us_since_epoch);

/// Every header field before the channel blocks, in the sensor's own units.
struct LmdTelegramHeader {
  bool is_stream_event = true;  ///< "sSN" (stream) or "sRA" (poll reply)
  uint32_t version = 1;
  uint32_t device_number = 1;
  uint32_t serial_number = 0x8D4C04;
  uint32_t device_status[2] = {0, 0};  ///< "0 0" OK; the first scans after start can be "1 0"
  uint16_t telegram_counter = 0;
  uint16_t scan_counter = 0;
  uint32_t time_since_startup_us = 0;    ///< device clock at beam 0 (wraps)
  uint32_t time_of_transmission_us = 0;  ///< device clock when sent (wraps)
  uint32_t digital_inputs[2] = {0, 0};
  uint32_t digital_outputs[2] = {7, 0};         ///< real ASCII LMS111 telegrams show "7 0"
  uint32_t reserved = 0;                        ///< layer angle on other models, 0 on LMS1xx
  uint32_t scan_frequency_1e2hz = 5000;         ///< 5000 = 50 Hz, 2500 = 25 Hz
  uint32_t measurement_frequency_1e1khz = 360;  ///< beam rate [kHz x 10] (360 = 36 kHz)
};

/// Which optional parts follow the DIST1 channel (sWN LMDscandatacfg, §4.2).
struct LmdOutputOptions {
  int rssi_bits = 16;  ///< 16: RSSI1 in the 16-bit block; 8: in the 8-bit block; 0: none
  bool send_device_name = false;
  std::string device_name = "LMS100";
  bool send_comment = false;
  std::string comment;
  bool send_time_info = false;
  LmdCalendarTime time_info;
};

/// Angular layout shared by every channel of the telegram.
struct LmdBeamLayout {
  int32_t start_angle_1e4deg = -450000;  ///< sensor angle of beam 0 [deg x 1e4]
  uint32_t step_1e4deg = 5000;           ///< [deg x 1e4]
};

/// Replaces out with the payload (no STX/ETX) of one LMDscandata telegram with
/// num_beams DIST1 values and, per options.rssi_bits, as many RSSI1 values.
/// out keeps its capacity, so encoding scans of one shape does not allocate.
void encode_lmd_scandata(const LmdTelegramHeader& header, const LmdBeamLayout& layout,
                         const uint16_t* dist_mm, const uint16_t* rssi, size_t num_beams,
                         const LmdOutputOptions& options, std::string& out);

/// The same telegram as a CoLa-B payload (no framing): the head "sSN LMDscandata " and every
/// field big-endian at its fixed width (§3; laid out as in the recorded LMS111/LMS511 sessions).
void encode_lmd_scandata_cola_b(const LmdTelegramHeader& header, const LmdBeamLayout& layout,
                                const uint16_t* dist_mm, const uint16_t* rssi, size_t num_beams,
                                const LmdOutputOptions& options, std::string& out);

}  // namespace refloc
