#include "common/lcm_conversions.hpp"

namespace refloc {

laser_scan_t to_lcm(const LaserScan& scan) {
  laser_scan_t msg;
  msg.utime = scan.utime;
  msg.receive_utime = scan.receive_utime;
  msg.sensor_start_us = scan.sensor_start_us;
  msg.sensor_transmit_us = scan.sensor_transmit_us;
  msg.scan_counter = static_cast<int32_t>(scan.scan_counter);
  msg.telegram_counter = static_cast<int32_t>(scan.telegram_counter);
  msg.device_status = static_cast<int32_t>(scan.device_status);
  msg.serial_number = static_cast<int32_t>(scan.serial_number);
  msg.start_angle = static_cast<float>(scan.start_angle);
  msg.angle_increment = static_cast<float>(scan.angle_increment);
  msg.time_increment = static_cast<float>(scan.time_increment);
  msg.scan_period = static_cast<float>(scan.scan_period);
  msg.range_min = static_cast<float>(scan.range_min);
  msg.range_max = static_cast<float>(scan.range_max);
  msg.ranges = scan.ranges;
  msg.nranges = static_cast<int32_t>(msg.ranges.size());  // LCM trusts the length field
  msg.rssi = scan.rssi;
  msg.nrssi = static_cast<int32_t>(msg.rssi.size());
  msg.rssi_bits = static_cast<int8_t>(msg.nrssi > 0 ? scan.rssi_bits : 0);
  return msg;
}

bool from_lcm(const laser_scan_t& msg, LaserScan& out) {
  if (msg.nrssi != 0 && msg.nrssi != msg.nranges) return false;
  if (!(msg.angle_increment != 0.0f) || msg.time_increment < 0.0f) return false;
  copy_from_lcm(msg, out);
  return true;
}

void copy_from_lcm(const laser_scan_t& msg, LaserScan& out) {
  out.utime = msg.utime;
  out.receive_utime = msg.receive_utime;
  out.sensor_start_us = msg.sensor_start_us;
  out.sensor_transmit_us = msg.sensor_transmit_us;
  out.scan_counter = static_cast<uint32_t>(msg.scan_counter);
  out.telegram_counter = static_cast<uint32_t>(msg.telegram_counter);
  out.device_status = static_cast<uint32_t>(msg.device_status);
  out.serial_number = static_cast<uint32_t>(msg.serial_number);
  out.start_angle = msg.start_angle;
  out.angle_increment = msg.angle_increment;
  out.time_increment = msg.time_increment;
  out.scan_period = msg.scan_period;
  out.range_min = msg.range_min;
  out.range_max = msg.range_max;
  out.ranges = msg.ranges;
  out.rssi = msg.rssi;
  out.rssi_bits = msg.rssi_bits;
}

reflector_t to_lcm(const ReflectorDetection& d) {
  reflector_t r{};
  r.x = d.laser_p_center.x();
  r.y = d.laser_p_center.y();
  r.covariance[0] = d.covariance(0, 0);
  r.covariance[1] = d.covariance(0, 1);
  r.covariance[2] = d.covariance(1, 0);
  r.covariance[3] = d.covariance(1, 1);
  r.range = d.range;
  r.bearing = d.bearing;
  r.utime = d.utime;
  r.first_beam = d.first_beam;
  r.nbeams = d.num_beams;
  r.mean_rssi = static_cast<float>(d.mean_rssi);
  r.roundness_m = static_cast<float>(d.roundness_m);
  r.fitted_radius_m = static_cast<float>(d.fitted_radius_m);
  return r;
}

ReflectorDetection from_lcm(const reflector_t& r) {
  ReflectorDetection d;
  d.laser_p_center = {r.x, r.y};
  d.covariance << r.covariance[0], r.covariance[1], r.covariance[2], r.covariance[3];
  d.range = r.range;
  d.bearing = r.bearing;
  d.utime = r.utime;
  d.first_beam = r.first_beam;
  d.num_beams = r.nbeams;
  d.mean_rssi = r.mean_rssi;
  d.roundness_m = r.roundness_m;
  d.fitted_radius_m = r.fitted_radius_m;
  return d;
}

void covariance_to_lcm(const Eigen::Matrix3d& covariance, double (&out)[9]) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out[3 * r + c] = covariance(r, c);
}

Eigen::Matrix3d covariance_from_lcm(const double (&in)[9]) {
  Eigen::Matrix3d covariance;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) covariance(r, c) = in[3 * r + c];
  return covariance;
}

void matches_from_message(const reflector_matches_t& msg, std::vector<ReflectorDetection>& detections,
                          std::vector<ReflectorMatch>& matches) {
  detections.clear();
  matches.clear();
  for (const reflector_match_t& m : msg.matches) {
    matches.push_back({static_cast<int>(detections.size()), m.map_id, {m.map_x, m.map_y}, m.map_radius});
    detections.push_back(from_lcm(m.detection));
  }
}

}  // namespace refloc
