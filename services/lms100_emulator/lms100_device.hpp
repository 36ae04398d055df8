#pragma once
// The command side of an emulated LMS100: login levels, scan and output
// configuration, measurement state, and the exact CoLa-A reply to every request
// a driver sends (docs/lms100-protocol.md §4.1, §4.2, §7). No sockets here: the
// server feeds request payloads in and sends the replies out.

#include "lms100_emulator/scan_scheduler.hpp"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace refloc {

struct Lms100DeviceConfig {
  uint32_t serial_number = 0x8D4C04;                   ///< in every telegram (real LMS111 sample value)
  std::string device_ident_name = "LMS10x_FieldEval";  ///< sRA DeviceIdent (real LMS100 reply)
  std::string device_ident_version = "V1.36-21.10.2010";
  std::string firmware_version = "V1.80.2";   ///< sRA FirmwareVersion
  std::string location_name = "not defined";  ///< LocationName and the telegram's device name
  uint32_t scan_frequency_1e2hz = 5000;       ///< at power-up: 5000 (50 Hz) or 2500 (25 Hz)
  uint32_t angular_resolution_1e4deg = 5000;  ///< at power-up: 5000 (0.5 deg) or 2500 (0.25 deg)
  double spin_up_s = 0.2;                     ///< start of measurement to STlms 7 [s] (real: ~30 s)
  bool measuring_at_power_up = true;          ///< a real LMS100 spins up by itself after power-on
  /// LMS100/LMS151 report 0.5 deg in LMPoutputRange even while scanning at 0.25 deg
  /// (clearpath #51, PR #39); keep true to emulate that lie.
  bool output_range_reports_half_degree = true;
  bool rssi_enabled = true;  ///< LMDscandatacfg at power-up (the stored setting)
  bool rssi_16bit = true;
  bool time_info = false;
  uint16_t first_scan_counter = 0;
};

/// What sWN LMDscandatacfg selected (§2.2).
struct LmdDataConfig {
  bool rssi_enabled = true;
  bool rssi_16bit = true;
  bool position = false;  ///< accepted, but the position block is always sent empty
  bool device_name = false;
  bool comment = false;
  bool time_info = false;
  uint32_t output_interval = 1;  ///< send every n-th scan
};

/// The beams that go into a telegram after LMPoutputRange is applied.
struct OutputBeams {
  int first_index = 0;  ///< index of the first output beam within the full scan
  int count = 0;
  int32_t start_angle_1e4deg = 0;  ///< sensor angle of the first output beam
  uint32_t step_1e4deg = 0;
};

class Lms100Device {
 public:
  explicit Lms100Device(const Lms100DeviceConfig& config);

  enum class Action {
    reply,            ///< send reply
    reply_with_scan,  ///< sRN LMDscandata: the caller sends the last scan as sRA LMDscandata
  };
  /// Handles one request payload (no STX/ETX) at device time now_us and writes the reply payload.
  Action handle_request(std::string_view payload, uint64_t now_us, std::string& reply);

  /// A client went away: its login and stream subscription end with it.
  void on_client_disconnected();

  /// sFA 4 for the next variable write (as seen right after power-up, sick_scan #44).
  void arm_refuse_next_write() { refuse_next_write_ = true; }
  void set_refuse_readiness(bool refuse) { scheduler_.set_refuse_readiness(refuse); }

  ScanScheduler& scheduler() { return scheduler_; }
  const ScanScheduler& scheduler() const { return scheduler_; }
  bool stream_enabled() const { return stream_enabled_; }
  int login_level() const { return login_level_; }
  const LmdDataConfig& data_config() const { return data_config_; }
  const Lms100DeviceConfig& config() const { return config_; }
  uint32_t scan_frequency_1e2hz() const { return frequency_1e2hz_; }
  uint32_t angular_resolution_1e4deg() const { return resolution_1e4deg_; }
  /// Number of beams of a full scan (541 at 0.5 deg).
  int full_scan_beams() const;
  OutputBeams output_beams() const;

  static constexpr int32_t kMinAngle1e4deg = -450000;
  static constexpr int32_t kMaxAngle1e4deg = 2250000;

 private:
  void handle_method(const std::vector<std::string_view>& t, uint64_t now_us, std::string& reply);
  void handle_read(const std::vector<std::string_view>& t, uint64_t now_us, std::string& reply,
                   Action& action);
  void handle_write(const std::vector<std::string_view>& t, std::string& reply);
  void handle_event(const std::vector<std::string_view>& t, std::string& reply);
  void set_access_mode(const std::vector<std::string_view>& t, std::string& reply);
  void set_scan_config(const std::vector<std::string_view>& t, uint64_t now_us, std::string& reply);
  void write_output_range(const std::vector<std::string_view>& t, std::string& reply);
  void write_data_config(const std::vector<std::string_view>& t, std::string& reply);
  void append_scan_config(std::string& reply) const;
  void append_status(uint64_t now_us, std::string& reply) const;

  Lms100DeviceConfig config_;
  ScanScheduler scheduler_;
  uint32_t frequency_1e2hz_;
  uint32_t resolution_1e4deg_;
  int32_t scan_start_1e4deg_ = kMinAngle1e4deg;
  int32_t scan_stop_1e4deg_ = kMaxAngle1e4deg;
  int32_t output_start_1e4deg_ = kMinAngle1e4deg;
  int32_t output_stop_1e4deg_ = kMaxAngle1e4deg;
  LmdDataConfig data_config_;
  int login_level_ = 0;
  bool stream_enabled_ = false;
  bool refuse_next_write_ = false;
  std::vector<std::string_view> tokens_;
};

}  // namespace refloc
