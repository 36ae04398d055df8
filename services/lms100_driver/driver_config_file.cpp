#include "lms100_driver/driver_config_file.hpp"

namespace refloc {

DriverServiceConfig parse_driver_config(const JsonConfig& file) {
  DriverServiceConfig c;
  Lms100SessionConfig& s = c.session;
  s.host = file.string("/host", s.host);
  if (s.host.empty()) file.fail("/host", "must not be empty (the sensor's address, e.g. 192.168.0.1)");
  s.dialect = file.choice("/protocol", "cola_a", {"cola_a", "cola_b"}) == "cola_b" ? ColaDialect::kColaB
                                                                                   : ColaDialect::kColaA;
  s.port = static_cast<uint16_t>(file.integer("/port", default_port(s.dialect), 1, 65535));
  const std::string device_name = file.string("/device", s.device.name);
  const DeviceProfile* device = find_device_profile(device_name);
  if (device == nullptr)
    file.fail("/device", "expected one of " + device_profile_names() + ", got '" + device_name + "'");
  s.device = *device;

  const double frequency_hz = file.number("/frequency_hz", s.device.default_frequency_hz, 1, 100);
  bool frequency_known = false;
  for (const double f : s.device.scan_frequencies_hz) frequency_known = frequency_known || f == frequency_hz;
  if (!frequency_known) {
    std::string allowed;
    for (const double f : s.device.scan_frequencies_hz)
      allowed += (allowed.empty() ? "" : ", ") + std::to_string(static_cast<int>(f));
    file.fail("/frequency_hz", "expected one of " + allowed + " for device " + s.device.name);
  }
  const double resolution_deg = file.number("/resolution_deg", 0.5, 0.25, 0.5);
  if (resolution_deg != 0.25 && resolution_deg != 0.5) file.fail("/resolution_deg", "expected 0.5 or 0.25");
  if (frequency_hz == 50 && resolution_deg == 0.25) {
    file.fail("/resolution_deg",
              "0.25 deg needs frequency_hz 25 (the LMS1xx offers 50/0.5, 25/0.25, 25/0.5)");
  }
  s.scan.frequency_1e2hz = static_cast<uint32_t>(frequency_hz * 100);
  s.scan.resolution_1e4deg = resolution_deg == 0.25 ? 2500 : 5000;
  s.set_scan_config = file.boolean("/set_scan_config", s.device.lms1xx_scan_config);
  if (s.set_scan_config && !s.device.lms1xx_scan_config) {
    file.fail("/set_scan_config",
              "the driver's mLMPsetscancfg is the LMS1xx's (-45..225 deg); set the scan "
              "configuration of a " +
                  s.device.name + " with SOPAS ET and set this false");
  }

  const long long rssi_bits = file.integer("/rssi_bits", s.device.default_rssi_bits, 0, 16);
  if (rssi_bits != 0 && rssi_bits != 8 && rssi_bits != 16)
    file.fail("/rssi_bits", "expected 16, 8 or 0 (off)");
  s.output.rssi = rssi_bits != 0;
  s.output.rssi_16bit = rssi_bits == 16;
  s.output.time_info = file.boolean("/time_info", s.output.time_info);

  s.connect_timeout_s = file.number("/connect_timeout_s", s.connect_timeout_s, 0.05, 60);
  s.reply_timeout_s = file.number("/reply_timeout_s", s.reply_timeout_s, 0.05, 60);
  s.ready_timeout_s = file.number("/ready_timeout_s", s.ready_timeout_s, 0.1, 600);
  s.status_poll_period_s = file.number("/status_poll_period_s", s.status_poll_period_s, 0.01, 10);
  s.first_scan_timeout_s = file.number("/first_scan_timeout_s", s.first_scan_timeout_s, 0.05, 60);
  s.scan_timeout_periods = file.number("/scan_timeout_periods", s.scan_timeout_periods, 1.5, 500);
  s.backoff_initial_s = file.number("/backoff_initial_s", s.backoff_initial_s, 0.01, 60);
  s.backoff_max_s = file.number("/backoff_max_s", s.backoff_max_s, s.backoff_initial_s, 600);
  s.max_parse_error_streak =
      static_cast<uint32_t>(file.integer("/max_parse_error_streak", s.max_parse_error_streak, 1, 1000));
  s.stamping.clock.bin_s = file.number("/clock_bin_s", s.stamping.clock.bin_s, 0.1, 60);
  s.stamping.clock.window_bins = static_cast<size_t>(
      file.integer("/clock_window_bins", static_cast<long long>(s.stamping.clock.window_bins), 5,
                   static_cast<long long>(SensorClockFilter::kMaxBins)));
  s.stamping.settle_reads = static_cast<size_t>(
      file.integer("/clock_settle_reads", static_cast<long long>(s.stamping.settle_reads), 1, 25));
  c.output_channel = file.string("/output_channel", c.output_channel);
  if (c.output_channel.empty()) file.fail("/output_channel", "must not be empty");
  c.error_after_s = file.number("/error_after_s", c.error_after_s, 0.1, 3600);
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
