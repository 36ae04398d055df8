#pragma once
// web_console's LCM edge: the lcmtypes the console shows as its plain inputs, and a command from
// the page as the nav_goal_t it publishes. Header only and outside the LCM-free library.

#include "common/heartbeat_state_name.hpp"
#include "web_console/client_request.hpp"
#include "web_console/console_inputs.hpp"

#include <refloc/heartbeat_t.hpp>
#include <refloc/laser_scan_t.hpp>
#include <refloc/map_health_t.hpp>
#include <refloc/nav_goal_t.hpp>
#include <refloc/nav_status_t.hpp>
#include <refloc/pose2d_t.hpp>
#include <refloc/reflector_clusters_t.hpp>
#include <refloc/reflector_detections_t.hpp>
#include <refloc/reflector_matches_t.hpp>

#include <algorithm>
#include <string>

namespace refloc {

inline std::string state_name(int value, std::initializer_list<const char*> names) {
  return value >= 0 && value < static_cast<int>(names.size()) ? names.begin()[value]
                                                              : "STATE_" + std::to_string(value);
}

inline ConsoleScan from_message(const laser_scan_t& m) {
  ConsoleScan s;
  s.utime = m.utime;
  s.start_angle = m.start_angle;
  s.angle_increment = m.angle_increment;
  s.ranges = m.ranges;
  s.rssi = m.rssi;
  s.rssi_bits = m.rssi_bits;
  return s;
}

inline ConsoleDetection from_message(const reflector_t& r) {
  return {r.x, r.y, r.range, r.bearing, r.first_beam, r.nbeams, r.mean_rssi, r.fitted_radius_m};
}

inline ConsoleDetections from_message(const reflector_detections_t& m) {
  ConsoleDetections d{m.utime, m.clusters_considered, m.clusters_rejected, {}};
  for (const reflector_t& r : m.reflectors) d.detections.push_back(from_message(r));
  return d;
}

inline ConsoleClusters from_message(const reflector_clusters_t& m) {
  ConsoleClusters c{m.utime, m.energy_threshold_8bit, m.energy_threshold_raw, m.rssi_read_as_8bit != 0, {}};
  for (const reflector_cluster_t& k : m.clusters)
    c.clusters.push_back({k.first_beam, k.last_beam, k.nbeams,
                          state_name(k.outcome, {"accepted", "too_few_beams", "too_wide", "too_narrow",
                                                 "not_round", "radius", "occluded", "fit_failed"}),
                          k.range, k.bearing, k.max_rssi_8bit});
  return c;
}

inline ConsoleMatches from_message(const reflector_matches_t& m) {
  ConsoleMatches c;
  c.utime = m.utime;
  c.status = state_name(m.status, {"OK", "AMBIGUOUS", "LOST"});
  c.mode = state_name(m.mode, {"tracking", "global"});
  c.map_T_laser = {m.hypothesis_x, m.hypothesis_y, m.hypothesis_theta};
  c.detections = m.ndetections;
  for (const reflector_match_t& p : m.matches)
    c.matches.push_back({p.map_id, p.map_x, p.map_y, p.detection.x, p.detection.y});
  return c;
}

inline ConsolePose from_message(const pose2d_t& m) {
  ConsolePose p;
  p.utime = m.utime;
  std::tie(p.x, p.y, p.theta) = std::tie(m.x, m.y, m.theta);
  std::copy(std::begin(m.covariance), std::end(m.covariance), p.covariance.begin());
  p.status = state_name(m.status, {"OK", "DEGRADED", "LOST", "AMBIGUOUS", "INITIALIZING"});
  p.reflectors_used = m.reflectors_used;
  return p;
}

inline ConsoleGoal from_message(const nav_goal_t& m) {
  ConsoleGoal g{m.goal_id, {}};
  for (size_t i = 0; i < m.x.size() && i < m.y.size() && i < m.theta.size(); ++i)
    g.waypoints.push_back({m.x[i], m.y[i], m.theta[i]});
  return g;
}

inline ConsoleNavStatus from_message(const nav_status_t& m) {
  return {m.goal_id,        state_name(m.state, {"IDLE", "DRIVING", "ARRIVED", "STOPPED_NO_POSE", "ABORTED"}),
          m.waypoint_index, m.waypoints_reached,
          m.nwaypoints,     m.distance_to_waypoint,
          m.heading_error,  m.reason};
}

inline ConsoleHeartbeat from_message(const heartbeat_t& m) {
  ConsoleHeartbeat h;
  h.utime = m.utime;
  h.service = m.service;
  h.pid = m.pid;
  h.state = heartbeat_state_name(m.state);
  h.detail = m.state_detail;
  h.uptime_s = static_cast<double>(m.uptime_us) * 1e-6;
  h.messages_in = m.messages_in;
  h.messages_out = m.messages_out;
  h.decode_errors = m.decode_errors;
  h.processing_p50_us = m.processing_p50_us;
  h.processing_p99_us = m.processing_p99_us;
  for (size_t i = 0; i < m.counter_names.size() && i < m.counter_values.size(); ++i)
    h.counters.emplace_back(m.counter_names[i], m.counter_values[i]);
  return h;
}

inline ConsoleMapHealth from_message(const map_health_t& m) {
  ConsoleMapHealth h{m.map_id, m.map_version, m.scans_used, {}, {}};
  for (const map_reflector_health_t& r : m.reflectors)
    h.reflectors.push_back({r.id, state_name(r.state, {"ok", "missing", "moved", "unconfirmed"}), r.seen,
                            r.expected_missing, r.offset_x, r.offset_y});
  for (const map_candidate_t& c : m.candidates)
    h.candidates.push_back({c.x, c.y, c.sightings, c.moved_reflector_id});
  return h;
}

/// A goal: one waypoint, the navigator's default tolerances and speed; stop: no waypoint
/// (the navigator cancels the goal and stops).
inline nav_goal_t to_message(const ConsoleCommand& command, int64_t utime, int64_t goal_id) {
  nav_goal_t goal{};
  goal.utime = utime;
  goal.goal_id = goal_id;
  if (command.kind == ConsoleCommand::Kind::kGoal) {
    goal.x = {command.x};
    goal.y = {command.y};
    goal.theta = {command.theta};
  }
  goal.nwaypoints = static_cast<int32_t>(goal.x.size());
  return goal;
}

/// The page's "the robot is here": map_T_robot with the configured std devs, status OK (the
/// matcher takes it as a prior and verifies it; pose_fusion does not read it).
inline pose2d_t initial_pose_message(const ConsoleCommand& command, int64_t utime, double sigma_m,
                                     double sigma_rad) {
  pose2d_t pose{};
  pose.utime = utime;
  pose.x = command.x;
  pose.y = command.y;
  pose.theta = command.theta;
  pose.covariance[0] = pose.covariance[4] = sigma_m * sigma_m;
  pose.covariance[8] = sigma_rad * sigma_rad;
  pose.status = pose2d_t::STATUS_OK;
  return pose;
}

}  // namespace refloc
