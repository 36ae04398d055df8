#include "lms100_driver/cola_a_commands.hpp"

#include <fmt/format.h>

#include "lms100_driver/cola_a_tokenizer.hpp"

namespace refloc {

std::string request_login() { return "sMN SetAccessMode 03 F4724744"; }

std::string request_read_scan_config() { return "sRN LMPscancfg"; }

std::string request_set_scan_config(const ScanConfig& c) {
  return fmt::format("sMN mLMPsetscancfg {:+d} +1 {:+d} {:+d} {:+d}", static_cast<int64_t>(c.frequency_1e2hz),
                     static_cast<int64_t>(c.resolution_1e4deg), c.start_angle_1e4deg, c.stop_angle_1e4deg);
}

std::string request_set_scandata_output(const ScanDataOutputConfig& c) {
  // Fields: echo mask (2 tokens), remission, remission resolution, unit, encoder (2 tokens),
  // position, name, comment, time info, output interval (decimal with sign).
  return fmt::format("sWN LMDscandatacfg 01 00 {:d} {:d} 0 00 00 0 {:d} {:d} {:d} {:+d}", c.rssi ? 1 : 0,
                     c.rssi_16bit ? 1 : 0, c.device_name ? 1 : 0, c.comment ? 1 : 0, c.time_info ? 1 : 0,
                     static_cast<int64_t>(c.output_interval));
}

std::string request_start_measurement() { return "sMN LMCstartmeas"; }
std::string request_stop_measurement() { return "sMN LMCstopmeas"; }
std::string request_run() { return "sMN Run"; }
std::string request_read_status() { return "sRN STlms"; }
std::string request_read_device_state() { return "sRN SCdevicestate"; }
std::string request_scandata_stream(bool on) { return on ? "sEN LMDscandata 1" : "sEN LMDscandata 0"; }

bool split_cola_a(std::string_view payload, ColaAMessage& out) {
  const size_t first = payload.find(' ');
  out.type = payload.substr(0, first);
  out.name = {};
  out.args = {};
  if (out.type.size() != 3) return false;
  if (first == std::string_view::npos) return true;
  const std::string_view rest = payload.substr(first + 1);
  if (out.type == "sFA") {  // "sFA <code>": no name
    out.args = rest;
    return true;
  }
  const size_t second = rest.find(' ');
  out.name = rest.substr(0, second);
  if (second != std::string_view::npos) out.args = rest.substr(second + 1);
  return true;
}

std::string_view expected_reply_type(std::string_view request_type) {
  if (request_type == "sRN") return "sRA";
  if (request_type == "sWN") return "sWA";
  if (request_type == "sMN") return "sAN";
  if (request_type == "sEN") return "sEA";
  return {};
}

bool is_reply_to(std::string_view request, std::string_view payload) {
  ColaAMessage req;
  ColaAMessage rep;
  if (!split_cola_a(request, req) || !split_cola_a(payload, rep)) return false;
  if (rep.name != req.name) return false;
  const std::string_view expected = expected_reply_type(req.type);
  return rep.type == expected || (req.type == "sMN" && rep.type == "sMA");
}

bool parse_sopas_error(std::string_view payload, uint32_t& code) {
  ColaAMessage m;
  if (!split_cola_a(payload, m) || m.type != "sFA") return false;
  return ColaATokenizer::parse_hex(m.args, code);
}

const char* sopas_error_name(uint32_t code) {
  static constexpr const char* kNames[] = {"Sopas_Ok",
                                           "METHODIN_ACCESSDENIED",
                                           "METHODIN_UNKNOWNINDEX",
                                           "VARIABLE_UNKNOWNINDEX",
                                           "LOCALCONDITIONFAILED",
                                           "INVALID_DATA",
                                           "UNKNOWN_ERROR",
                                           "BUFFER_OVERFLOW",
                                           "BUFFER_UNDERFLOW",
                                           "ERROR_UNKNOWN_TYPE",
                                           "VARIABLE_WRITE_ACCESSDENIED",
                                           "UNKNOWN_CMD_FOR_NAMESERVER",
                                           "UNKNOWN_COLA_COMMAND",
                                           "METHODIN_SERVER_BUSY",
                                           "FLEX_OUT_OF_BOUNDS",
                                           "EVENTREG_UNKNOWNINDEX",
                                           "COLA_A_VALUE_OVERFLOW",
                                           "COLA_A_INVALID_CHARACTER",
                                           "OSAI_NO_MESSAGE",
                                           "OSAI_NO_ANSWER_MESSAGE",
                                           "INTERNAL",
                                           "HubAddressCorrupted",
                                           "HubAddressDecoding",
                                           "HubAddressAddressExceeded",
                                           "HubAddressBlankExpected",
                                           "AsyncMethodsAreSuppressed"};
  if (code < sizeof(kNames) / sizeof(kNames[0])) return kNames[code];
  if (code == 32) return "ComplexArraysNotSupported";
  return "unknown";
}

namespace {

/// Checks "type name" and returns a tokenizer positioned on the arguments.
ParseResult expect_head(std::string_view payload, std::string_view type, std::string_view name,
                        ColaAMessage& m) {
  uint32_t code = 0;
  if (parse_sopas_error(payload, code)) {
    return ParseResult::failure(
        fmt::format("{} {}: sensor error sFA {:X} ({})", type, name, code, sopas_error_name(code)));
  }
  if (!split_cola_a(payload, m) || m.type != type || m.name != name) {
    return ParseResult::failure(fmt::format("expected '{} {}', got '{}'", type, name, payload.substr(0, 60)));
  }
  return ParseResult::success();
}

}  // namespace

ParseResult check_login_reply(std::string_view payload) {
  ColaAMessage m;
  if (auto r = expect_head(payload, "sAN", "SetAccessMode", m); !r) return r;
  if (m.args != "1")
    return ParseResult::failure("login refused (SetAccessMode answered " + std::string(m.args) + ")");
  return ParseResult::success();
}

ParseResult check_scan_config_reply(std::string_view payload, const ScanConfig& requested) {
  ColaAMessage m;
  if (auto r = expect_head(payload, "sAN", "mLMPsetscancfg", m); !r) return r;
  ColaATokenizer tok(m.args);
  uint32_t err = 0;
  uint32_t freq = 0;
  uint32_t sectors = 0;
  uint32_t res = 0;
  int32_t start = 0;
  int32_t stop = 0;
  if (!tok.hex_u32(err)) return ParseResult::failure("mLMPsetscancfg reply: " + tok.error());
  static constexpr const char* kErrors[] = {"no error",
                                            "invalid frequency",
                                            "invalid angular resolution",
                                            "invalid frequency and resolution",
                                            "invalid scan area",
                                            "other error"};
  if (err != 0) {
    return ParseResult::failure(
        fmt::format("mLMPsetscancfg refused: error {} ({})", err, err < 6 ? kErrors[err] : "unknown"));
  }
  if (!tok.hex_u32(freq) || !tok.hex_u32(sectors) || !tok.hex_u32(res) || !tok.hex_i32(start) ||
      !tok.hex_i32(stop)) {
    return ParseResult::failure("mLMPsetscancfg reply: " + tok.error());
  }
  if (freq != requested.frequency_1e2hz || res != requested.resolution_1e4deg) {
    return ParseResult::failure(
        fmt::format("mLMPsetscancfg echoed {} (1/100 Hz) / {} (1/10000 deg), asked {} / {}", freq, res,
                    requested.frequency_1e2hz, requested.resolution_1e4deg));
  }
  return ParseResult::success();
}

ParseResult parse_scan_config_reply(std::string_view payload, ScanConfig& out) {
  ColaAMessage m;
  if (auto r = expect_head(payload, "sRA", "LMPscancfg", m); !r) return r;
  ColaATokenizer tok(m.args);
  uint32_t sectors = 0;
  if (!tok.hex_u32(out.frequency_1e2hz) || !tok.hex_u32(sectors) || !tok.hex_u32(out.resolution_1e4deg) ||
      !tok.hex_i32(out.start_angle_1e4deg) || !tok.hex_i32(out.stop_angle_1e4deg)) {
    return ParseResult::failure("LMPscancfg reply: " + tok.error());
  }
  return ParseResult::success();
}

ParseResult check_simple_reply(std::string_view payload, std::string_view expected) {
  uint32_t code = 0;
  if (parse_sopas_error(payload, code)) {
    return ParseResult::failure(
        fmt::format("'{}': sensor error sFA {:X} ({})", expected, code, sopas_error_name(code)));
  }
  if (payload != expected) {
    return ParseResult::failure(fmt::format("expected '{}', got '{}'", expected, payload.substr(0, 60)));
  }
  return ParseResult::success();
}

ParseResult parse_status_reply(std::string_view payload, uint32_t& status) {
  ColaAMessage m;
  if (auto r = expect_head(payload, "sRA", "STlms", m); !r) return r;
  ColaATokenizer tok(m.args);
  if (!tok.hex_u32(status, 0xFF)) return ParseResult::failure("STlms status: " + tok.error());
  return ParseResult::success();
}

ParseResult parse_device_state_reply(std::string_view payload, uint32_t& state) {
  ColaAMessage m;
  if (auto r = expect_head(payload, "sRA", "SCdevicestate", m); !r) return r;
  ColaATokenizer tok(m.args);
  if (!tok.hex_u32(state, 0xFF)) return ParseResult::failure("SCdevicestate: " + tok.error());
  return ParseResult::success();
}

}  // namespace refloc
