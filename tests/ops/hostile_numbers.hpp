#pragma once
// Every floating-point field of every refloc message, by name: how the hostile-bus log check
// finds a non-finite value on any channel the stack publishes.

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/map_health_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/odometry_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_clusters_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>
#include <refloc/twist_t.hpp>
#include <refloc/wheel_encoders_t.hpp>

#include <cmath>
#include <cstdint>
#include <string>

namespace refloc::hostile {

/// Visit(name, value) for each floating-point field.
template <class Visit>
void numbers(const pose2d_t& m, Visit&& v) {
  v("x", m.x), v("y", m.y), v("theta", m.theta), v("residual", m.residual);
  for (double c : m.covariance) v("covariance", c);
}
template <class Visit>
void numbers(const odometry_t& m, Visit&& v) {
  v("x", m.x), v("y", m.y), v("theta", m.theta), v("vx", m.vx), v("vy", m.vy), v("wz", m.wz);
  v("distance", m.distance), v("slip_indicator", m.slip_indicator);
  for (double c : m.covariance) v("covariance", c);
}
template <class Visit>
void numbers(const twist_t& m, Visit&& v) {
  v("vx", m.vx), v("vy", m.vy), v("wz", m.wz);
}
template <class Visit>
void numbers(const reflector_t& m, Visit&& v) {
  v("x", m.x), v("y", m.y), v("range", m.range), v("bearing", m.bearing), v("mean_rssi", m.mean_rssi);
  v("roundness_m", m.roundness_m), v("fitted_radius_m", m.fitted_radius_m);
  for (double c : m.covariance) v("covariance", c);
}
template <class Visit>
void numbers(const laser_scan_t& m, Visit&& v) {
  v("start_angle", m.start_angle), v("angle_increment", m.angle_increment),
      v("time_increment", m.time_increment);
  v("scan_period", m.scan_period), v("range_min", m.range_min), v("range_max", m.range_max);
  for (float r : m.ranges) v("ranges", r);
}
template <class Visit>
void numbers(const reflector_detections_t& m, Visit&& v) {
  for (const auto& r : m.reflectors) numbers(r, v);
}
template <class Visit>
void numbers(const reflector_matches_t& m, Visit&& v) {
  v("hypothesis_score", m.hypothesis_score), v("runner_up_score", m.runner_up_score);
  v("hypothesis_x", m.hypothesis_x), v("hypothesis_y", m.hypothesis_y),
      v("hypothesis_theta", m.hypothesis_theta);
  for (const auto& match : m.matches) {
    numbers(match.detection, v);
    v("map_x", match.map_x), v("map_y", match.map_y), v("map_radius", match.map_radius);
  }
}
template <class Visit>
void numbers(const nav_goal_t& m, Visit&& v) {
  v("xy_tolerance", m.xy_tolerance), v("heading_tolerance", m.heading_tolerance), v("max_speed", m.max_speed);
  for (double x : m.x) v("x", x);
  for (double y : m.y) v("y", y);
  for (double t : m.theta) v("theta", t);
}
template <class Visit>
void numbers(const nav_status_t& m, Visit&& v) {
  v("distance_to_waypoint", m.distance_to_waypoint), v("heading_error", m.heading_error);
}
template <class Visit>
void numbers(const heartbeat_t& m, Visit&& v) {
  v("processing_p50_us", m.processing_p50_us), v("processing_p99_us", m.processing_p99_us);
}
template <class Visit>
void numbers(const wheel_encoders_t&, Visit&&) {}
template <class Visit>
void numbers(const reflector_clusters_t& m, Visit&& v) {
  v("energy_threshold_8bit", m.energy_threshold_8bit), v("energy_threshold_raw", m.energy_threshold_raw);
  for (const auto& c : m.clusters)
    v("range", c.range), v("bearing", c.bearing), v("max_rssi_8bit", c.max_rssi_8bit);
}
template <class Visit>
void numbers(const map_health_t& m, Visit&& v) {
  for (const auto& r : m.reflectors) {
    v("map_x", r.map_x), v("map_y", r.map_y), v("offset_x", r.offset_x), v("offset_y", r.offset_y);
    v("offset_sigma_x", r.offset_sigma_x), v("offset_sigma_y", r.offset_sigma_y);
  }
  for (const auto& c : m.candidates) {
    v("x", c.x), v("y", c.y), v("sigma_x", c.sigma_x), v("sigma_y", c.sigma_y);
    v("viewpoint_spread", c.viewpoint_spread);
  }
}

/// The first non-finite field of m ("" when all are finite).
template <class Message>
std::string first_non_finite(const Message& m) {
  std::string found;
  numbers(m, [&found](const char* name, double value) {
    if (found.empty() && !std::isfinite(value)) found = std::string(name) + "=" + std::to_string(value);
  });
  return found;
}

}  // namespace refloc::hostile
