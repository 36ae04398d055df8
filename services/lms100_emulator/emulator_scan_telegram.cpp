// Lms100Emulator's scan telegrams: which scans go out (stream on, output interval, the
// drop fault), the beam times and angles the scan source renders, and the LMDscandata
// header fields, coded by lmd_scandata_encoder.
#include "lms100_emulator/emulator_server.hpp"
#include "lms100_emulator/lmd_scandata_encoder.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

void Lms100Emulator::Server::emit_scan(const ScanSlot& slot, bool stream) {
  if (client_fd < 0) return;
  const LmdDataConfig& data = device.data_config();
  if (stream) {
    if (!device.stream_enabled()) return;
    if (data.output_interval > 1 && slot.scan_counter % data.output_interval != 0) return;
    if (faults.take_drop()) {
      std::lock_guard<std::mutex> lock(stats_mutex);
      ++stats.scans_dropped;
      return;
    }
  }
  const OutputBeams beams = device.output_beams();
  const auto first_beam_offset_us =
      static_cast<uint64_t>(std::llround(beams.first_index * kTimeIncrementS * 1e6));

  ScanRequest scan;
  scan.first_beam_sensor_us = slot.start_us + first_beam_offset_us;
  scan.first_beam_utime = power_up_utime + static_cast<int64_t>(scan.first_beam_sensor_us);
  scan.time_increment_s = kTimeIncrementS;
  scan.num_beams = beams.count;
  // Sensor angles run -45..225 deg with 90 deg straight ahead; the laser frame has 0 ahead.
  scan.start_angle_rad = (beams.start_angle_1e4deg * 1e-4 - 90.0) * kDegToRad;
  scan.angle_increment_rad = beams.step_1e4deg * 1e-4 * kDegToRad;
  scan.scan_counter = slot.scan_counter;
  scan.rssi_bits = data.rssi_enabled ? (data.rssi_16bit ? 16 : 8) : 0;
  dist_mm.assign(static_cast<size_t>(beams.count), 0);
  rssi.assign(static_cast<size_t>(beams.count), 0);
  if (source) source(scan, dist_mm, rssi);

  LmdTelegramHeader header;
  header.is_stream_event = stream;
  header.serial_number = device.config().serial_number;
  header.device_status[0] = (stream && stream_telegrams < config.startup_status_scans) ? 1 : 0;
  header.telegram_counter = telegram_counter;
  header.scan_counter = slot.scan_counter;
  header.time_since_startup_us = static_cast<uint32_t>(config.power_up_clock_us + scan.first_beam_sensor_us);
  // Stamped as the bytes leave (after rendering, which a real device does while it spins), less
  // the hidden link delay; never before the scan was ready. Stamped at the slot's due time instead,
  // the render time became a link delay the driver cannot see (0.8 ms in Release, more sanitized).
  const auto link_delay_us = static_cast<uint64_t>(std::llround(config.link_delay_s * 1e6));
  const uint64_t ready_us = slot.complete_us > link_delay_us ? slot.complete_us - link_delay_us : 0;
  const uint64_t now_us = device_now();
  const uint64_t transmit_us = std::max(ready_us, now_us > link_delay_us ? now_us - link_delay_us : 0);
  header.time_of_transmission_us = static_cast<uint32_t>(config.power_up_clock_us + transmit_us);
  header.scan_frequency_1e2hz = device.scan_frequency_1e2hz();
  header.measurement_frequency_1e1khz = kMeasurementFrequency1e1khz;
  header.reserved = settings.layer_angle_1e4deg;  // the multi-layer fault; 0 on an LMS1xx

  LmdOutputOptions options;
  options.rssi_bits = scan.rssi_bits;
  options.send_device_name = data.device_name;
  options.device_name = device.config().location_name;
  options.send_comment = data.comment;
  options.send_time_info = data.time_info;
  options.time_info = calendar_time_from_epoch_us(
      config.rtc_from_host_clock ? static_cast<uint64_t>(scan.first_beam_utime) : scan.first_beam_sensor_us);
  LmdBeamLayout layout;
  layout.start_angle_1e4deg = beams.start_angle_1e4deg;
  layout.step_1e4deg = beams.step_1e4deg;
  if (config.cola_b) {  // the header faults rewrite CoLa-A text: CoLa-A only
    encode_lmd_scandata_cola_b(header, layout, dist_mm.data(), rssi.data(), dist_mm.size(), options, body);
  } else {
    encode_lmd_scandata(header, layout, dist_mm.data(), rssi.data(), dist_mm.size(), options, body);
    corrupt_scan_header(settings, body);  // the implausible-header faults; no-op by default
  }

  telegram_counter = static_cast<uint16_t>(telegram_counter + 1);
  if (stream) {
    ++stream_telegrams;
    std::lock_guard<std::mutex> lock(stats_mutex);
    ++stats.scan_telegrams_sent;
  }
  send_frame(body, stream);
}

}  // namespace refloc
