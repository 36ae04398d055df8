#include "lms100_emulator/lmd_scandata_encoder.hpp"

#include "lms100_emulator/cola_a_text.hpp"

#include <algorithm>
#include <ctime>

namespace refloc {

LmdCalendarTime calendar_time_from_epoch_us(uint64_t us_since_epoch) {
  const auto seconds = static_cast<std::time_t>(us_since_epoch / 1000000u);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  LmdCalendarTime t;
  t.year = static_cast<uint32_t>(tm.tm_year + 1900);
  t.month = static_cast<uint32_t>(tm.tm_mon + 1);
  t.day = static_cast<uint32_t>(tm.tm_mday);
  t.hour = static_cast<uint32_t>(tm.tm_hour);
  t.minute = static_cast<uint32_t>(tm.tm_min);
  t.second = static_cast<uint32_t>(tm.tm_sec);
  t.microsecond = static_cast<uint32_t>(us_since_epoch % 1000000u);
  return t;
}

namespace {

void append_field(std::string& out, uint32_t value) {
  out.push_back(' ');
  append_cola_hex(out, value);
}

void append_channel(std::string& out, const char* name, const LmdBeamLayout& layout, const uint16_t* values,
                    size_t count, uint16_t max_value) {
  out.push_back(' ');
  out.append(name);
  out.push_back(' ');
  append_cola_hex_float(out, 1.0F);  // scale: LMS1xx always sends 1.0
  out.push_back(' ');
  append_cola_hex_float(out, 0.0F);  // offset
  out.push_back(' ');
  append_cola_hex_i32(out, layout.start_angle_1e4deg);
  append_field(out, layout.step_1e4deg);
  append_field(out, static_cast<uint32_t>(count));
  for (size_t i = 0; i < count; ++i) append_field(out, std::min(values[i], max_value));
}

}  // namespace

void encode_lmd_scandata(const LmdTelegramHeader& header, const LmdBeamLayout& layout,
                         const uint16_t* dist_mm, const uint16_t* rssi, size_t num_beams,
                         const LmdOutputOptions& options, std::string& out) {
  out.clear();
  out.append(header.is_stream_event ? "sSN LMDscandata" : "sRA LMDscandata");
  append_field(out, header.version);
  append_field(out, header.device_number);
  append_field(out, header.serial_number);
  append_field(out, header.device_status[0]);
  append_field(out, header.device_status[1]);
  append_field(out, header.telegram_counter);
  append_field(out, header.scan_counter);
  append_field(out, header.time_since_startup_us);
  append_field(out, header.time_of_transmission_us);
  append_field(out, header.digital_inputs[0]);
  append_field(out, header.digital_inputs[1]);
  append_field(out, header.digital_outputs[0]);
  append_field(out, header.digital_outputs[1]);
  append_field(out, header.reserved);
  append_field(out, header.scan_frequency_1e2hz);
  append_field(out, header.measurement_frequency_1e1khz);
  append_field(out, 0);  // number of encoders: the LMS100 has no encoder input in use

  // An empty scan (output range outside the scan area) still announces its RSSI channel.
  const bool have_rssi = rssi != nullptr || num_beams == 0;
  const bool rssi16 = options.rssi_bits == 16 && have_rssi;
  const bool rssi8 = options.rssi_bits == 8 && have_rssi;
  append_field(out, rssi16 ? 2 : 1);
  append_channel(out, "DIST1", layout, dist_mm, num_beams, 0xFFFF);
  if (rssi16) append_channel(out, "RSSI1", layout, rssi, num_beams, 0xFFFF);
  append_field(out, rssi8 ? 1 : 0);
  if (rssi8) append_channel(out, "RSSI1", layout, rssi, num_beams, 0xFF);

  append_field(out, 0);  // position block: no LMS1xx sends it
  if (options.send_device_name) {
    append_field(out, 1);
    out.push_back(' ');
    append_cola_string(out, options.device_name);
  } else {
    append_field(out, 0);
  }
  if (options.send_comment) {
    append_field(out, 1);
    out.push_back(' ');
    append_cola_string(out, options.comment);
  } else {
    append_field(out, 0);
  }
  if (options.send_time_info) {
    const LmdCalendarTime& t = options.time_info;
    append_field(out, 1);
    append_field(out, t.year);
    append_field(out, t.month);
    append_field(out, t.day);
    append_field(out, t.hour);
    append_field(out, t.minute);
    append_field(out, t.second);
    append_field(out, t.microsecond);
  } else {
    append_field(out, 0);
  }
  append_field(out, 0);  // event block
}

}  // namespace refloc
