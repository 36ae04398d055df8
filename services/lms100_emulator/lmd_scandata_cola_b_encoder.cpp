// LMDscandata in CoLa-B: the fields of lmd_scandata_encoder.cpp in the same order, each at its
// binary width (uint8 status/IO bytes and flags' contents, uint16 counters and counts, uint32
// clocks and frequencies, float32 scale/offset, int32 start angle).
#include "lms100_emulator/lmd_scandata_encoder.hpp"

#include "lms100_emulator/cola_b_wire.hpp"

#include <algorithm>
#include <cstring>

namespace refloc {
namespace {

void put_float(std::string& out, float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  put_big_endian(out, bits, 4);
}

void put_channel(std::string& out, const char* name, const LmdBeamLayout& layout, const uint16_t* values,
                 size_t count, size_t value_bytes) {
  out.append(name, 5);
  put_float(out, 1.0F);  // scale: LMS1xx always sends 1.0
  put_float(out, 0.0F);  // offset
  put_big_endian(out, static_cast<uint32_t>(layout.start_angle_1e4deg), 4);
  put_big_endian(out, layout.step_1e4deg, 2);
  put_big_endian(out, static_cast<uint32_t>(count), 2);
  const uint16_t max_value = value_bytes == 1 ? 0xFF : 0xFFFF;
  for (size_t i = 0; i < count; ++i) put_big_endian(out, std::min(values[i], max_value), value_bytes);
}

void put_string(std::string& out, const std::string& text) {
  put_big_endian(out, static_cast<uint32_t>(text.size()), 2);
  out.append(text);
}

}  // namespace

void encode_lmd_scandata_cola_b(const LmdTelegramHeader& h, const LmdBeamLayout& layout,
                                const uint16_t* dist_mm, const uint16_t* rssi, size_t num_beams,
                                const LmdOutputOptions& options, std::string& out) {
  out.clear();
  out.append(h.is_stream_event ? "sSN LMDscandata " : "sRA LMDscandata ");
  put_big_endian(out, h.version, 2);
  put_big_endian(out, h.device_number, 2);
  put_big_endian(out, h.serial_number, 4);
  put_big_endian(out, h.device_status[0], 1);
  put_big_endian(out, h.device_status[1], 1);
  put_big_endian(out, h.telegram_counter, 2);
  put_big_endian(out, h.scan_counter, 2);
  put_big_endian(out, h.time_since_startup_us, 4);
  put_big_endian(out, h.time_of_transmission_us, 4);
  put_big_endian(out, h.digital_inputs[0], 1);
  put_big_endian(out, h.digital_inputs[1], 1);
  put_big_endian(out, h.digital_outputs[0], 1);
  put_big_endian(out, h.digital_outputs[1], 1);
  put_big_endian(out, h.reserved, 2);
  put_big_endian(out, h.scan_frequency_1e2hz, 4);
  put_big_endian(out, h.measurement_frequency_1e1khz, 4);
  put_big_endian(out, 0, 2);  // no encoders

  const bool have_rssi = rssi != nullptr || num_beams == 0;
  const bool rssi16 = options.rssi_bits == 16 && have_rssi;
  const bool rssi8 = options.rssi_bits == 8 && have_rssi;
  put_big_endian(out, rssi16 ? 2 : 1, 2);
  put_channel(out, "DIST1", layout, dist_mm, num_beams, 2);
  if (rssi16) put_channel(out, "RSSI1", layout, rssi, num_beams, 2);
  put_big_endian(out, rssi8 ? 1 : 0, 2);
  if (rssi8) put_channel(out, "RSSI1", layout, rssi, num_beams, 1);

  put_big_endian(out, 0, 2);  // position block
  put_big_endian(out, options.send_device_name ? 1 : 0, 2);
  if (options.send_device_name) put_string(out, options.device_name);
  put_big_endian(out, options.send_comment ? 1 : 0, 2);
  if (options.send_comment) put_string(out, options.comment);
  put_big_endian(out, options.send_time_info ? 1 : 0, 2);
  if (options.send_time_info) {
    const LmdCalendarTime& t = options.time_info;
    put_big_endian(out, t.year, 2);
    for (const uint32_t v : {t.month, t.day, t.hour, t.minute, t.second}) put_big_endian(out, v, 1);
    put_big_endian(out, t.microsecond, 4);
  }
  put_big_endian(out, 0, 2);  // event block
}

}  // namespace refloc
