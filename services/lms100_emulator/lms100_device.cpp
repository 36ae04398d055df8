#include "lms100_emulator/lms100_device.hpp"

#include "lms100_emulator/cola_a_text.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"

#include <algorithm>
#include <cstdio>

namespace refloc {

namespace {

// SOPAS error codes (LMS100_PROTOCOL.md §1.3 table).
constexpr uint32_t kErrAccessDenied = 0x1;
constexpr uint32_t kErrUnknownMethod = 0x2;
constexpr uint32_t kErrUnknownVariable = 0x3;
constexpr uint32_t kErrLocalCondition = 0x4;
constexpr uint32_t kErrInvalidData = 0x5;
constexpr uint32_t kErrTooManyParameters = 0x7;  // BUFFER_OVERFLOW; our reading, not seen from a device
constexpr uint32_t kErrTooFewParameters = 0x8;
constexpr uint32_t kErrWriteAccessDenied = 0xA;
constexpr uint32_t kErrUnknownCommand = 0xC;
constexpr uint32_t kErrUnknownEvent = 0xF;
constexpr uint32_t kErrInvalidCharacter = 0x11;

constexpr int kLevelAuthorizedClient = 3;

void error_reply(uint32_t code, std::string& reply) {
  reply = "sFA ";
  append_cola_hex(reply, code);
}

uint64_t period_us_for(uint32_t frequency_1e2hz) { return 100000000ULL / frequency_1e2hz; }

/// False (and an sFA reply) unless the request has exactly n arguments after its name.
bool expect_arguments(const std::vector<std::string_view>& t, size_t n, std::string& reply) {
  const size_t have = t.size() - 2;
  if (have < n) {
    error_reply(kErrTooFewParameters, reply);
    return false;
  }
  if (have > n) {
    error_reply(kErrTooManyParameters, reply);
    return false;
  }
  return true;
}

/// Reads arguments first..first+n-1 as numbers; sFA 5 on a bad one.
bool read_numbers(const std::vector<std::string_view>& t, size_t first, size_t n, int64_t* out,
                  std::string& reply) {
  for (size_t i = 0; i < n; ++i) {
    if (!parse_cola_request_number(t[first + i], out[i])) {
      error_reply(kErrInvalidData, reply);
      return false;
    }
  }
  return true;
}

bool is_flag(int64_t v) { return v == 0 || v == 1; }

}  // namespace

Lms100Device::Lms100Device(const Lms100DeviceConfig& config)
    : config_(config),
      scheduler_(static_cast<uint64_t>(config.spin_up_s * 1e6), period_us_for(config.scan_frequency_1e2hz),
                 config.first_scan_counter),
      frequency_1e2hz_(config.scan_frequency_1e2hz),
      resolution_1e4deg_(config.angular_resolution_1e4deg) {
  data_config_.rssi_enabled = config.rssi_enabled;
  data_config_.rssi_16bit = config.rssi_16bit;
  data_config_.time_info = config.time_info;
  if (config.measuring_at_power_up) scheduler_.start(0);
}

int Lms100Device::full_scan_beams() const {
  return static_cast<int>((scan_stop_1e4deg_ - scan_start_1e4deg_) /
                          static_cast<int32_t>(resolution_1e4deg_)) +
         1;
}

OutputBeams Lms100Device::output_beams() const {
  const auto res = static_cast<int64_t>(resolution_1e4deg_);
  const int64_t lo = std::max(scan_start_1e4deg_, output_start_1e4deg_) - int64_t{scan_start_1e4deg_};
  const int64_t hi = std::min(scan_stop_1e4deg_, output_stop_1e4deg_) - int64_t{scan_start_1e4deg_};
  OutputBeams beams;
  beams.step_1e4deg = resolution_1e4deg_;
  const int64_t first = (lo + res - 1) / res;
  const int64_t last = hi >= 0 ? hi / res : -1;
  beams.first_index = static_cast<int>(first);
  beams.count = static_cast<int>(std::max<int64_t>(0, last - first + 1));
  beams.start_angle_1e4deg = static_cast<int32_t>(scan_start_1e4deg_ + first * res);
  return beams;
}

void Lms100Device::on_client_disconnected() {
  login_level_ = 0;
  stream_enabled_ = false;
}

Lms100Device::Action Lms100Device::handle_request(std::string_view payload, uint64_t now_us,
                                                  std::string& reply) {
  reply.clear();
  Action action = Action::reply;
  if (!is_printable_cola_text(payload)) {
    error_reply(kErrInvalidCharacter, reply);
    return action;
  }
  split_cola_tokens(payload, tokens_);
  if (tokens_.size() < 2 || tokens_[1].empty()) {
    error_reply(kErrUnknownCommand, reply);
    return action;
  }
  const std::string_view type = tokens_[0];
  if (type == "sMN") {
    handle_method(tokens_, now_us, reply);
  } else if (type == "sRN") {
    handle_read(tokens_, now_us, reply, action);
  } else if (type == "sWN") {
    handle_write(tokens_, reply);
  } else if (type == "sEN") {
    handle_event(tokens_, reply);
  } else {
    error_reply(kErrUnknownCommand, reply);
  }
  return action;
}

void Lms100Device::handle_method(const std::vector<std::string_view>& t, uint64_t now_us,
                                 std::string& reply) {
  const std::string_view name = t[1];
  if (name == "SetAccessMode") {
    set_access_mode(t, reply);
    return;
  }
  if (name == "Run") {
    if (!expect_arguments(t, 0, reply)) return;
    login_level_ = 0;  // Run ends the configuration session (logs out)
    reply = "sAN Run 1";
    return;
  }
  const bool known = name == "mLMPsetscancfg" || name == "LMCstartmeas" || name == "LMCstopmeas" ||
                     name == "LMCstandby" || name == "mEEwriteall";
  if (!known) {
    error_reply(kErrUnknownMethod, reply);
    return;
  }
  if (login_level_ < kLevelAuthorizedClient) {
    error_reply(kErrAccessDenied, reply);
    return;
  }
  if (name == "mLMPsetscancfg") {
    set_scan_config(t, now_us, reply);
    return;
  }
  if (!expect_arguments(t, 0, reply)) return;
  reply = "sAN ";
  reply.append(name.data(), name.size());
  if (name == "LMCstartmeas") {
    scheduler_.start(now_us);
    reply += " 0";
  } else if (name == "LMCstopmeas" || name == "LMCstandby") {
    scheduler_.stop();
    reply += " 0";
  } else {  // mEEwriteall: nothing to persist in an emulator
    reply += " 1";
  }
}

void Lms100Device::set_access_mode(const std::vector<std::string_view>& t, std::string& reply) {
  if (!expect_arguments(t, 2, reply)) return;
  int64_t values[2];
  if (!read_numbers(t, 2, 2, values, reply)) return;
  // Level hashes from martinteuchler/LMS1xx colaa.cpp: 02 maintenance, 03 authorized client, 04 service.
  const auto hash = static_cast<uint32_t>(values[1]);
  const bool ok = (values[0] == 2 && hash == 0xB21ACE26u) || (values[0] == 3 && hash == 0xF4724744u) ||
                  (values[0] == 4 && hash == 0x81BE23AAu);
  if (ok) login_level_ = static_cast<int>(values[0]);
  reply = ok ? "sAN SetAccessMode 1" : "sAN SetAccessMode 0";
}

void Lms100Device::set_scan_config(const std::vector<std::string_view>& t, uint64_t now_us,
                                   std::string& reply) {
  if (!expect_arguments(t, 5, reply)) return;
  int64_t v[5];
  if (!read_numbers(t, 2, 5, v, reply)) return;
  const int64_t frequency = v[0], sectors = v[1], resolution = v[2], start = v[3], stop = v[4];
  const bool frequency_ok = frequency == 2500 || frequency == 5000;
  // An LMS1xx offers 25 Hz at 0.25 or 0.5 deg and 50 Hz at 0.5 deg only.
  const bool resolution_ok = resolution == 5000 || (resolution == 2500 && frequency != 5000);
  const bool area_ok = sectors == 1 && start >= kMinAngle1e4deg && stop <= kMaxAngle1e4deg && start < stop;
  uint32_t error = 0;
  if (!frequency_ok && !resolution_ok) {
    error = 3;
  } else if (!frequency_ok) {
    error = 1;
  } else if (!resolution_ok) {
    error = 2;
  } else if (!area_ok) {
    error = 4;
  }
  if (error == 0) {
    const bool respin = frequency != frequency_1e2hz_ || resolution != resolution_1e4deg_;
    frequency_1e2hz_ = static_cast<uint32_t>(frequency);
    resolution_1e4deg_ = static_cast<uint32_t>(resolution);
    scan_start_1e4deg_ = static_cast<int32_t>(start);
    scan_stop_1e4deg_ = static_cast<int32_t>(stop);
    if (respin) scheduler_.respin(now_us, period_us_for(frequency_1e2hz_));
  }
  // The reply echoes the configuration now in force (real: "sAN mLMPsetscancfg 0 9C4 1 9C4 FFF92230 225510").
  reply = "sAN mLMPsetscancfg ";
  append_cola_hex(reply, error);
  reply += ' ';
  append_cola_hex(reply, frequency_1e2hz_);
  reply += " 1 ";
  append_cola_hex(reply, resolution_1e4deg_);
  reply += ' ';
  append_cola_hex_i32(reply, scan_start_1e4deg_);
  reply += ' ';
  append_cola_hex_i32(reply, scan_stop_1e4deg_);
}

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
    append_cola_hex(reply, frequency_1e2hz_);
    reply += " 1 ";
    append_cola_hex(reply, resolution_1e4deg_);
    reply += ' ';
    append_cola_hex_i32(reply, scan_start_1e4deg_);
    reply += ' ';
    append_cola_hex_i32(reply, scan_stop_1e4deg_);
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

void Lms100Device::handle_event(const std::vector<std::string_view>& t, std::string& reply) {
  if (t[1] != "LMDscandata") {
    error_reply(kErrUnknownEvent, reply);
    return;
  }
  if (!expect_arguments(t, 1, reply)) return;
  int64_t on = 0;
  if (!read_numbers(t, 2, 1, &on, reply)) return;
  if (!is_flag(on)) {
    error_reply(kErrInvalidData, reply);
    return;
  }
  stream_enabled_ = on == 1;
  reply = stream_enabled_ ? "sEA LMDscandata 1" : "sEA LMDscandata 0";
}

}  // namespace refloc
