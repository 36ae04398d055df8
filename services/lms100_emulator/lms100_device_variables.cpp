// Lms100Device's variables: sRN reads (scan and output configuration, status, identity,
// LMDscandatacfg) and sWN writes (LMPoutputRange, LMDscandatacfg), docs/lms100-protocol.md §4.2.
#include "lms100_emulator/lms100_device.hpp"

#include "lms100_emulator/cola_a_text.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"
#include "lms100_emulator/sopas_reply.hpp"

#include <cstdio>

namespace refloc {

using namespace sopas;  // the reply vocabulary of every handler below

void Lms100Device::handle_read(const std::vector<std::string_view>& t, uint64_t now_us, std::string& reply,
                               Action& action) {
  const std::string_view name = t[1];
  const bool known = name == "LMPscancfg" || name == "LMPoutputRange" || name == "STlms" ||
                     name == "SCdevicestate" || name == "DeviceIdent" || name == "FirmwareVersion" ||
                     name == "SerialNumber" || name == "LocationName" || name == "LMDscandatacfg" ||
                     name == "LMDscandata";
  if (!known) {
    error_reply(kErrUnknownVariable, reply);
    return;
  }
  if (!expect_arguments(t, 0, reply)) return;
  reply = "sRA ";
  reply.append(name.data(), name.size());
  reply += ' ';
  if (name == "LMPscancfg") {
    append_scan_config(reply);
  } else if (name == "LMPoutputRange") {
    reply += "1 ";
    append_cola_hex(reply, config_.output_range_reports_half_degree ? 5000u : resolution_1e4deg_);
    reply += ' ';
    append_cola_hex_i32(reply, output_start_1e4deg_);
    reply += ' ';
    append_cola_hex_i32(reply, output_stop_1e4deg_);
  } else if (name == "STlms") {
    append_status(now_us, reply);
  } else if (name == "SCdevicestate") {
    // 0 busy while the motor spins up, 1 ready (sick_scan_xd waits for 1 after Run).
    const int status = scheduler_.status_code(now_us);
    reply += (scheduler_.measuring() && status != 7) ? '0' : '1';
  } else if (name == "DeviceIdent") {
    append_cola_string(reply, config_.device_ident_name);
    reply += ' ';
    append_cola_string(reply, config_.device_ident_version);
  } else if (name == "FirmwareVersion") {
    append_cola_string(reply, config_.firmware_version);
  } else if (name == "SerialNumber") {
    char digits[16];
    std::snprintf(digits, sizeof(digits), "%08u", config_.serial_number % 100000000u);
    append_cola_string(reply, digits);
  } else if (name == "LocationName") {
    append_cola_string(reply, config_.location_name);
  } else if (name == "LMDscandatacfg") {
    const LmdDataConfig& d = data_config_;
    reply += "1 0 ";
    reply += d.rssi_enabled ? "1 " : "0 ";
    reply += d.rssi_16bit ? "1 " : "0 ";
    reply += "0 0 0 ";
    reply += d.position ? "1 " : "0 ";
    reply += d.device_name ? "1 " : "0 ";
    reply += d.comment ? "1 " : "0 ";
    reply += d.time_info ? "1 " : "0 ";
    append_cola_hex(reply, d.output_interval);
  } else {  // LMDscandata: the caller fills in the last scan
    reply.clear();
    action = Action::reply_with_scan;
  }
}

// "<frequency> 1 <resolution> <start> <stop>": one sector, as the read of LMPscancfg and the
// answer to mLMPsetscancfg both carry it.
void Lms100Device::append_scan_config(std::string& reply) const {
  append_cola_hex(reply, frequency_1e2hz_);
  reply += " 1 ";
  append_cola_hex(reply, resolution_1e4deg_);
  reply += ' ';
  append_cola_hex_i32(reply, scan_start_1e4deg_);
  reply += ' ';
  append_cola_hex_i32(reply, scan_stop_1e4deg_);
}

void Lms100Device::append_status(uint64_t now_us, std::string& reply) const {
  // Real: "sRA STlms 3 0 8 00:17:28 A 01.01.1970 0 0 0"; the clock is the unset RTC (uptime).
  const LmdCalendarTime rtc = calendar_time_from_epoch_us(now_us);
  char text[64];
  std::snprintf(text, sizeof(text), "%d 0 8 %02u:%02u:%02u A %02u.%02u.%04u 0 0 0",
                scheduler_.status_code(now_us), rtc.hour, rtc.minute, rtc.second, rtc.day, rtc.month,
                rtc.year);
  reply += text;
}

void Lms100Device::handle_write(const std::vector<std::string_view>& t, std::string& reply) {
  const std::string_view name = t[1];
  const bool writable = name == "LMPoutputRange" || name == "LMDscandatacfg";
  const bool read_only = name == "LMPscancfg" || name == "STlms" || name == "SCdevicestate" ||
                         name == "DeviceIdent" || name == "FirmwareVersion" || name == "SerialNumber" ||
                         name == "LMDscandata" || name == "LocationName";
  if (!writable && !read_only) {
    error_reply(kErrUnknownVariable, reply);
    return;
  }
  if (read_only || login_level_ < kLevelAuthorizedClient) {
    error_reply(kErrWriteAccessDenied, reply);
    return;
  }
  if (refuse_next_write_) {
    refuse_next_write_ = false;
    error_reply(kErrLocalCondition, reply);
    return;
  }
  if (name == "LMPoutputRange") {
    write_output_range(t, reply);
  } else {
    write_data_config(t, reply);
  }
}

void Lms100Device::write_output_range(const std::vector<std::string_view>& t, std::string& reply) {
  if (!expect_arguments(t, 4, reply)) return;
  int64_t v[4];
  if (!read_numbers(t, 2, 4, v, reply)) return;
  const int64_t sectors = v[0], start = v[2], stop = v[3];
  if (sectors != 1 || start < kMinAngle1e4deg || stop > kMaxAngle1e4deg || start > stop) {
    error_reply(kErrInvalidData, reply);
    return;
  }
  // The resolution field cannot change the scan resolution (LMS4000 OI); it is ignored.
  output_start_1e4deg_ = static_cast<int32_t>(start);
  output_stop_1e4deg_ = static_cast<int32_t>(stop);
  reply = "sWA LMPoutputRange";
}

void Lms100Device::write_data_config(const std::vector<std::string_view>& t, std::string& reply) {
  // 01 00 <rssi> <rssi 16 bit> <unit> <encoder 2 tokens> <position> <name> <comment> <time> <interval>
  if (!expect_arguments(t, 12, reply)) return;
  int64_t v[12];
  if (!read_numbers(t, 2, 12, v, reply)) return;
  // Only the first echo and no encoder are emulated: other values are refused, not silently ignored.
  const bool ok = v[0] == 1 && v[1] == 0 && is_flag(v[2]) && is_flag(v[3]) && v[4] == 0 && v[5] == 0 &&
                  v[6] == 0 && is_flag(v[7]) && is_flag(v[8]) && is_flag(v[9]) && is_flag(v[10]) &&
                  v[11] >= 1 && v[11] <= 50000;
  if (!ok) {
    error_reply(kErrInvalidData, reply);
    return;
  }
  data_config_.rssi_enabled = v[2] == 1;
  data_config_.rssi_16bit = v[3] == 1;
  data_config_.position = v[7] == 1;
  data_config_.device_name = v[8] == 1;
  data_config_.comment = v[9] == 1;
  data_config_.time_info = v[10] == 1;
  data_config_.output_interval = static_cast<uint32_t>(v[11]);
  reply = "sWA LMDscandatacfg";
}

}  // namespace refloc
