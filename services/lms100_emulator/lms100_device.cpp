#include "lms100_emulator/lms100_device.hpp"

#include "lms100_emulator/cola_a_text.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"
#include "lms100_emulator/sopas_reply.hpp"

#include <algorithm>
#include <cstdio>

namespace refloc {

using namespace sopas;  // the reply vocabulary of every handler below

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
  append_scan_config(reply);
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
