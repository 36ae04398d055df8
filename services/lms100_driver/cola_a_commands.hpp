#pragma once
// CoLa-A requests the driver sends and the interpretation of their replies
// (docs/lms100-protocol.md §4). Payloads only; frame_cola_a() adds STX/ETX.

#include <cstdint>
#include <string>
#include <string_view>

#include "lms100_driver/parse_result.hpp"

namespace refloc {

/// mLMPsetscancfg parameters. LMS1xx offers 50 Hz/0.5 deg, 25 Hz/0.25 deg and 25 Hz/0.5 deg.
struct ScanConfig {
  bool operator==(const ScanConfig& o) const {
    return frequency_1e2hz == o.frequency_1e2hz && resolution_1e4deg == o.resolution_1e4deg &&
           start_angle_1e4deg == o.start_angle_1e4deg && stop_angle_1e4deg == o.stop_angle_1e4deg;
  }

  uint32_t frequency_1e2hz = 5000;    ///< [Hz x 100]
  uint32_t resolution_1e4deg = 5000;  ///< [deg x 1e4]
  int32_t start_angle_1e4deg = -450000;
  int32_t stop_angle_1e4deg = 2250000;
};

/// LMDscandatacfg output options (§2.2).
struct ScanDataOutputConfig {
  bool rssi = true;        ///< needed for reflector detection
  bool rssi_16bit = true;  ///< false: 8-bit RSSI in the 8-bit channel block
  bool device_name = false;
  bool comment = false;
  bool time_info = true;
  uint32_t output_interval = 1;  ///< every n-th scan
};

/// sMN SetAccessMode 03 F4724744 (authorized client).
std::string request_login();
/// sRN LMPscancfg: the scan configuration in use.
std::string request_read_scan_config();
/// sMN mLMPsetscancfg +5000 +1 +5000 -450000 +2250000 (decimal with sign, as SICK's examples).
std::string request_set_scan_config(const ScanConfig& config);
/// sWN LMDscandatacfg 01 00 1 1 0 00 00 0 0 0 1 +1
std::string request_set_scandata_output(const ScanDataOutputConfig& config);
std::string request_start_measurement();       ///< sMN LMCstartmeas
std::string request_stop_measurement();        ///< sMN LMCstopmeas
std::string request_run();                     ///< sMN Run
std::string request_read_status();             ///< sRN STlms
std::string request_read_device_state();       ///< sRN SCdevicestate
std::string request_scandata_stream(bool on);  ///< sEN LMDscandata 1|0

/// The first two tokens of a telegram and the rest.
struct ColaAMessage {
  std::string_view type;  ///< sRA, sWA, sAN, sMA, sEA, sSN, sFA, ...
  std::string_view name;  ///< empty for sFA
  std::string_view args;  ///< everything after "type name ", may be empty
};
/// Splits a payload; false when it has no command type.
bool split_cola_a(std::string_view payload, ColaAMessage& out);

/// The reply type a request expects: sRN→sRA, sWN→sWA, sMN→sAN, sEN→sEA.
std::string_view expected_reply_type(std::string_view request_type);
/// True when payload answers request: same name and the expected type (sMN also accepts sMA).
bool is_reply_to(std::string_view request, std::string_view payload);

/// Decodes "sFA <hex code>"; false when payload is not an sFA.
bool parse_sopas_error(std::string_view payload, uint32_t& code);
/// The SOPAS name of an sFA code (e.g. 4 → "LOCALCONDITIONFAILED"); "unknown" if not in the table.
const char* sopas_error_name(uint32_t code);

/// sAN SetAccessMode 1 → ok; 0 → refused.
ParseResult check_login_reply(std::string_view payload);
/// sAN mLMPsetscancfg <err> <freq> <n> <res> <start> <stop>: err 0 and the echo equals the request.
ParseResult check_scan_config_reply(std::string_view payload, const ScanConfig& requested);
/// sRA LMPscancfg <freq> <n sectors> <res> <start> <stop> [further sectors]: the first sector.
ParseResult parse_scan_config_reply(std::string_view payload, ScanConfig& out);
/// sAN LMCstartmeas 0 / sAN LMCstopmeas 0 / sAN Run 1 / sWA ... / sEA LMDscandata n.
ParseResult check_simple_reply(std::string_view payload, std::string_view expected);
/// sRA STlms <status> ...: the status (7 = ready for measurement).
ParseResult parse_status_reply(std::string_view payload, uint32_t& status);
/// sRA SCdevicestate <n>: 0 busy, 1 ready, 2 error, 3 standby.
ParseResult parse_device_state_reply(std::string_view payload, uint32_t& state);

inline constexpr uint32_t kStatusReadyForMeasurement = 7;
inline constexpr uint32_t kDeviceStateReady = 1;

}  // namespace refloc
