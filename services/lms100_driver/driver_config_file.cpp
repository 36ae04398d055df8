#include "lms100_driver/driver_config_file.hpp"

namespace refloc {

DriverServiceConfig parse_driver_config(const JsonConfig& file) {
  DriverServiceConfig c;
  Lms100SessionConfig& s = c.session;
  s.host = file.string({"/host", "", "the sensor's IP address (factory 192.168.0.1); --host overrides it"},
                       s.host);
  if (s.host.empty()) file.fail("/host", "must not be empty (the sensor's address, e.g. 192.168.0.1)");
  const std::string protocol =
      file.choice({"/protocol", "",
                   "cola_a (ASCII) or cola_b (binary): the dialect the sensor's port speaks; never switched"},
                  "cola_a", {"cola_a", "cola_b"});
  s.dialect = protocol == "cola_b" ? ColaDialect::kColaB : ColaDialect::kColaA;
  s.port = static_cast<uint16_t>(file.integer(
      {"/port", "",
       "the sensor's TCP port: 2111 for cola_a, 2112 for cola_b by default; --port overrides it"},
      default_port(s.dialect), 1, 65535));
  const std::string device_name = file.choice(
      {"/device", "", "scanner family (lms1xx, lms5xx, tim5xx_7xx): range limits, frequencies, beams, field"},
      s.device.name, device_profile_name_set());
  const DeviceProfile* device = find_device_profile(device_name);
  if (device == nullptr)
    file.fail("/device", "expected one of " + device_profile_names() + ", got '" + device_name + "'");
  s.device = *device;

  const double frequency_hz =
      file.number({"/frequency_hz", "Hz",
                   "scan frequency: set on an LMS1xx (50 or 25); else the sensor's, for the scan timeout"},
                  s.device.default_frequency_hz, 1, 100);
  bool frequency_known = false;
  std::string allowed;
  for (const double f : s.device.scan_frequencies_hz) {
    frequency_known = frequency_known || f == frequency_hz;
    allowed += (allowed.empty() ? "" : ", ") + std::to_string(static_cast<int>(f));
  }
  if (!frequency_known)
    file.fail("/frequency_hz", "expected one of " + allowed + " for device " + s.device.name);
  const double resolution_deg = file.number(
      {"/resolution_deg", "deg", "angular resolution set on an LMS1xx: 0.5, or 0.25 at 25 Hz (1081 beams)"},
      0.5, 0.25, 0.5);
  if (resolution_deg != 0.25 && resolution_deg != 0.5) file.fail("/resolution_deg", "expected 0.5 or 0.25");
  if (frequency_hz == 50 && resolution_deg == 0.25) {
    file.fail("/resolution_deg",
              "0.25 deg needs frequency_hz 25 (the LMS1xx offers 50/0.5, 25/0.25, 25/0.5)");
  }
  s.scan.frequency_1e2hz = static_cast<uint32_t>(frequency_hz * 100);
  s.scan.resolution_1e4deg = resolution_deg == 0.25 ? 2500 : 5000;
  s.set_scan_config =
      file.boolean({"/set_scan_config", "",
                    "write frequency/resolution when the sensor differs (re-spins 30-45 s); LMS1xx only"},
                   s.device.lms1xx_scan_config);
  if (s.set_scan_config && !s.device.lms1xx_scan_config) {
    file.fail("/set_scan_config",
              "the driver's mLMPsetscancfg is the LMS1xx's (-45..225 deg); set the scan "
              "configuration of a " +
                  s.device.name + " with SOPAS ET and set this false");
  }

  const long long rssi_bits = file.integer(
      {"/rssi_bits", "bit", "RSSI resolution asked for: 16, 8 or 0 (none; reflector detection needs RSSI)"},
      s.device.default_rssi_bits, 0, 16);
  if (rssi_bits != 0 && rssi_bits != 8 && rssi_bits != 16)
    file.fail("/rssi_bits", "expected 16, 8 or 0 (off)");
  s.output.rssi = rssi_bits != 0;
  s.output.rssi_16bit = rssi_bits == 16;
  s.output.time_info = file.boolean(
      {"/time_info", "", "ask for the sensor's real-time-clock block (parsed, not used for stamps)"},
      s.output.time_info);

  s.connect_timeout_s = file.number(
      {"/connect_timeout_s", "s", "a TCP connect attempt gives up after this; raise on slow links"},
      s.connect_timeout_s, 0.05, 60);
  s.reply_timeout_s =
      file.number({"/reply_timeout_s", "s", "wait this long for each command's reply, then reconnect"},
                  s.reply_timeout_s, 0.05, 60);
  s.ready_timeout_s =
      file.number({"/ready_timeout_s", "s",
                   "wait for STlms 7 (ready); a real sensor needs 30-45 s after a scan config change"},
                  s.ready_timeout_s, 0.1, 600);
  s.status_poll_period_s =
      file.number({"/status_poll_period_s", "s", "how often STlms is read while waiting for ready"},
                  s.status_poll_period_s, 0.01, 10);
  s.first_scan_timeout_s = file.number(
      {"/first_scan_timeout_s", "s", "the first scan must come this soon after subscribing, else reconnect"},
      s.first_scan_timeout_s, 0.05, 60);
  s.scan_timeout_periods =
      file.number({"/scan_timeout_periods", "count",
                   "no scan for this many scan periods: reconnect; raise on a starved host"},
                  s.scan_timeout_periods, 1.5, 500);
  s.backoff_initial_s =
      file.number({"/backoff_initial_s", "s", "first wait before reconnecting; doubles per failed attempt"},
                  s.backoff_initial_s, 0.01, 60);
  s.backoff_max_s = file.number({"/backoff_max_s", "s", "longest wait between reconnect attempts"},
                                s.backoff_max_s, s.backoff_initial_s, 600);
  s.max_parse_error_streak = static_cast<uint32_t>(
      file.integer({"/max_parse_error_streak", "count", "this many unparsable scans in a row: reconnect"},
                   s.max_parse_error_streak, 1, 1000));
  s.stamping.clock.bin_s = file.number(
      {"/clock_bin_s", "s", "sensor clock fit: one lower-envelope sample per this much sensor time"},
      s.stamping.clock.bin_s, 0.1, 60);
  s.stamping.clock.window_bins = static_cast<size_t>(file.integer(
      {"/clock_window_bins", "count", "sensor clock fit: offset and drift over this many bins (60 = 1 min)"},
      static_cast<long long>(s.stamping.clock.window_bins), 5,
      static_cast<long long>(SensorClockFilter::kMaxBins)));
  s.stamping.settle_reads = static_cast<size_t>(
      file.integer({"/clock_settle_reads", "count",
                    "after a connect, hold scans until this many reads shaped the clock fit"},
                   static_cast<long long>(s.stamping.settle_reads), 1, 25));
  c.output_channel =
      file.string({"/output_channel", "", "LCM channel the scans are published on"}, c.output_channel);
  if (c.output_channel.empty()) file.fail("/output_channel", "must not be empty");
  c.error_after_s =
      file.number({"/error_after_s", "s", "no scan for this long: HEARTBEAT says ERROR (DEGRADED before)"},
                  c.error_after_s, 0.1, 3600);
  return c;
}

DriverServiceConfig load_driver_config_file(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  DriverServiceConfig config = parse_driver_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
