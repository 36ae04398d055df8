#include "lms100_emulator/emulator_config_loader.hpp"

#include "common/json_config.hpp"

#include <cmath>
#include <stdexcept>

namespace refloc {

WriteSplitMode parse_split_mode(const std::string& name) {
  if (name == "none") return WriteSplitMode::none;
  if (name == "random") return WriteSplitMode::random;
  if (name == "boundaries") return WriteSplitMode::boundaries;
  throw std::invalid_argument("split mode must be none, random or boundaries, got '" + name + "'");
}

Lms100EmulatorConfig parse_emulator_config(const JsonConfig& c) {
  Lms100EmulatorConfig out;
  out.bind_address =
      c.string({"/bind_address", "", "address the emulated sensor listens on"}, out.bind_address);
  out.cola_b = c.choice({"/protocol", "", "cola_a (ASCII) or cola_b (binary): the dialect it serves"},
                        "cola_a", {"cola_a", "cola_b"}) == "cola_b";
  out.port = static_cast<uint16_t>(
      c.integer({"/port", "", "TCP port: 2111 for cola_a, 2112 for cola_b by default; 0 = any free port"},
                out.cola_b ? 2112 : 2111, 0, 65535));

  Lms100DeviceConfig& d = out.device;
  const double frequency_hz = c.number({"/scan_frequency_hz", "Hz", "scan frequency at power-up: 25 or 50"},
                                       d.scan_frequency_1e2hz / 100.0, 25.0, 50.0);
  if (frequency_hz != 25.0 && frequency_hz != 50.0)
    c.fail("/scan_frequency_hz", "an LMS100 scans at 25 or 50 Hz");
  const double resolution_deg =
      c.number({"/angular_resolution_deg", "deg", "angular resolution at power-up: 0.5, or 0.25 at 25 Hz"},
               d.angular_resolution_1e4deg / 1e4, 0.25, 0.5);
  if (resolution_deg != 0.25 && resolution_deg != 0.5) {
    c.fail("/angular_resolution_deg", "an LMS100 resolves 0.25 or 0.5 deg");
  }
  if (frequency_hz == 50.0 && resolution_deg == 0.25) {
    c.fail("/angular_resolution_deg", "0.25 deg is only available at 25 Hz");
  }
  d.scan_frequency_1e2hz = static_cast<uint32_t>(std::lround(frequency_hz * 100.0));
  d.angular_resolution_1e4deg = static_cast<uint32_t>(std::lround(resolution_deg * 1e4));
  d.spin_up_s =
      c.number({"/spin_up_s", "s", "start of measurement to ready (STlms 7); a real unit takes ~30 s"},
               d.spin_up_s, 0.0, 120.0);
  d.measuring_at_power_up =
      c.boolean({"/measuring_at_power_up", "", "spin up by itself after power-on, as a real LMS100"},
                d.measuring_at_power_up);
  d.serial_number = static_cast<uint32_t>(c.integer(
      {"/serial_number", "", "serial number sent in every telegram"}, d.serial_number, 0, 0xFFFFFFFFLL));
  d.location_name =
      c.string({"/location_name", "", "LocationName and the telegram's device name"}, d.location_name);
  d.firmware_version =
      c.string({"/firmware_version", "", "answer to sRN FirmwareVersion"}, d.firmware_version);
  d.rssi_enabled =
      c.boolean({"/rssi_enabled", "", "RSSI channel on at power-up (until LMDscandatacfg)"}, d.rssi_enabled);
  d.rssi_16bit = c.boolean({"/rssi_16bit", "", "16-bit RSSI at power-up; false: 8-bit"}, d.rssi_16bit);
  d.time_info = c.boolean({"/time_info", "", "time-info block at power-up"}, d.time_info);
  d.output_range_reports_half_degree =
      c.boolean({"/output_range_reports_half_degree", "",
                 "LMPoutputRange says 0.5 deg even at 0.25 deg, as real LMS100/151 do"},
                d.output_range_reports_half_degree);
  d.first_scan_counter = static_cast<uint16_t>(
      c.integer({"/first_scan_counter", "count", "scan counter of the first scan; near 65535 tests the wrap"},
                0, 0, 65535));

  out.processing_delay_s = c.number({"/processing_delay_s", "s", "last beam to telegram ready"},
                                    out.processing_delay_s, 0.0, 0.004);
  out.link_delay_s = c.number(
      {"/link_delay_s", "s",
       "transmission stamp to bytes at the host, unseen by the host: the driver's stamps run this late"},
      out.link_delay_s, 0.0, 0.02);
  out.power_up_clock_us = static_cast<uint32_t>(
      c.integer({"/power_up_clock_us", "us", "sensor clock at power-up; near 2^32 tests its wrap"}, 0, 0,
                0xFFFFFFFFLL));
  out.first_telegram_counter = static_cast<uint16_t>(
      c.integer({"/first_telegram_counter", "count", "telegram counter of the first telegram"}, 0, 0, 65535));
  out.startup_status_scans =
      static_cast<int>(c.integer({"/startup_status_scans", "count",
                                  "stream telegrams with device status 1 0 after sEN (real LMS111: 7)"},
                                 0, 0, 1000));
  out.rtc_from_host_clock = c.boolean(
      {"/rtc_from_host_clock", "", "time-info block from host UTC instead of the unset RTC (1970 + uptime)"},
      out.rtc_from_host_clock);
  out.refuse_first_write_after_power_up = c.boolean(
      {"/refuse_first_write_after_power_up", "", "answer the first sWN with sFA 4, as seen on real units"},
      out.refuse_first_write_after_power_up);
  out.send_timeout_ms = static_cast<int>(
      c.integer({"/send_timeout_ms", "ms", "a client that does not read for this long is dropped"},
                out.send_timeout_ms, 10, 60000));
  out.random_seed = static_cast<uint32_t>(
      c.integer({"/random_seed", "", "seed of the split and junk faults"}, out.random_seed, 0, 0xFFFFFFFFLL));

  FaultSettings& f = out.faults;
  f.split_mode = parse_split_mode(
      c.choice({"/faults/split_mode", "", "fault: cut writes none, at random, or at telegram boundaries"},
               "none", {"none", "random", "boundaries"}));
  f.split_pieces = static_cast<int>(
      c.integer({"/faults/split_pieces", "count", "fault: pieces per split write"}, f.split_pieces, 2, 64));
  f.split_gap_ms = static_cast<int>(c.integer(
      {"/faults/split_gap_ms", "ms", "fault: pause between the pieces of a write"}, f.split_gap_ms, 0, 100));
  f.merge_scan_telegrams = static_cast<int>(c.integer(
      {"/faults/merge_scan_telegrams", "count", "fault: this many scan telegrams per write"}, 1, 1, 50));
  f.junk_bytes_between_telegrams = static_cast<int>(
      c.integer({"/faults/junk_bytes_between_telegrams", "count", "fault: junk bytes before every telegram"},
                0, 0, 10000));
  f.duplicate_replies =
      c.boolean({"/faults/duplicate_replies", "", "fault: send every command reply twice"}, false);
  f.refuse_readiness = c.boolean({"/faults/refuse_readiness", "", "fault: STlms never reaches 7"}, false);
  return out;
}

}  // namespace refloc
