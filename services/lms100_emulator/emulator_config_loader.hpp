#pragma once
// Reads Lms100EmulatorConfig from a JSON config (every key optional, defaults as
// in the structs, ranges validated, errors name file and JSON pointer).
//
//   {"bind_address": "127.0.0.1", "protocol": "cola_a", "port": 2111,
//    "scan_frequency_hz": 50, "angular_resolution_deg": 0.5, "spin_up_s": 0.2,
//    "measuring_at_power_up": true, "serial_number": 9260036, "location_name": "not defined",
//    "firmware_version": "V1.80.2", "rssi_enabled": true, "rssi_16bit": true, "time_info": false,
//    "output_range_reports_half_degree": true, "processing_delay_s": 0.001,
//    "power_up_clock_us": 0, "first_telegram_counter": 0, "first_scan_counter": 0,
//    "startup_status_scans": 0, "rtc_from_host_clock": false,
//    "refuse_first_write_after_power_up": false, "send_timeout_ms": 1000, "random_seed": 1,
//    "faults": {"split_mode": "none|random|boundaries", "split_pieces": 3, "split_gap_ms": 2,
//               "merge_scan_telegrams": 1, "junk_bytes_between_telegrams": 0,
//               "duplicate_replies": false, "refuse_readiness": false}}

#include "lms100_emulator/lms100_emulator.hpp"

#include <string>

namespace refloc {
class JsonConfig;

/// Reads the keys above at the document root; does not call reject_unknown_keys()
/// (the caller may read more keys from the same document).
Lms100EmulatorConfig parse_emulator_config(const JsonConfig& config);

/// "none", "random" or "boundaries"; throws std::invalid_argument otherwise.
WriteSplitMode parse_split_mode(const std::string& name);

}  // namespace refloc
