#pragma once
// The messages the console shows, as plain structs (web_console_messages.hpp fills them from the
// lcmtypes). Statuses and states arrive as their names ("OK", "DRIVING"): the page shows words.

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace refloc {

/// One LMS100_SCAN (laser_scan_t): beam i at start_angle + i * angle_increment, laser frame.
struct ConsoleScan {
  int64_t utime = 0;             ///< first beam [us]
  double start_angle = 0.0;      ///< [rad]
  double angle_increment = 0.0;  ///< [rad]
  std::vector<float> ranges;     ///< [m]; 0 = no echo
  std::vector<int32_t> rssi;     ///< empty, or one per beam, on the sensor's scale
  int rssi_bits = 0;             ///< 8 or 16; 0 without RSSI
};

/// One reflector of REFLECTORS (reflector_t), laser frame.
struct ConsoleDetection {
  double x = 0.0;        ///< [m]
  double y = 0.0;        ///< [m]
  double range = 0.0;    ///< [m]
  double bearing = 0.0;  ///< [rad]
  int first_beam = 0;
  int beams = 0;
  double mean_rssi = 0.0;
  double radius = 0.0;  ///< [m]
};

struct ConsoleDetections {
  int64_t utime = 0;  ///< [us]
  int clusters_considered = 0;
  int clusters_rejected = 0;
  std::vector<ConsoleDetection> detections;
};

/// One bright cluster of REFLECTOR_CLUSTERS (reflector_cluster_t).
struct ConsoleCluster {
  int first_beam = 0;
  int last_beam = 0;
  int beams = 0;
  std::string outcome;   ///< "accepted", or the reason it was rejected ("too_few_beams", ...)
  double range = 0.0;    ///< [m]
  double bearing = 0.0;  ///< [rad]
  double max_rssi_8bit = 0.0;
};

struct ConsoleClusters {
  int64_t utime = 0;  ///< [us], the scan's
  double energy_threshold_8bit = 0.0;
  double energy_threshold_raw = 0.0;  ///< on the scan's own RSSI scale
  bool rssi_read_as_8bit = false;
  std::vector<ConsoleCluster> clusters;
};

/// One pair of REFLECTOR_MATCHES: a detection (laser frame) and the map reflector it is.
struct ConsoleMatch {
  int map_id = 0;
  double map_x = 0.0;    ///< [m]
  double map_y = 0.0;    ///< [m]
  double laser_x = 0.0;  ///< [m]
  double laser_y = 0.0;  ///< [m]
};

struct ConsoleMatches {
  int64_t utime = 0;                    ///< [us]
  std::string status;                   ///< OK, AMBIGUOUS, LOST
  std::string mode;                     ///< tracking, global
  std::array<double, 3> map_T_laser{};  ///< the hypothesis (x [m], y [m], theta [rad])
  int detections = 0;
  std::vector<ConsoleMatch> matches;
};

/// POSE, LASER_POSE or GROUND_TRUTH (pose2d_t).
struct ConsolePose {
  int64_t utime = 0;                   ///< [us]
  double x = 0.0;                      ///< [m]
  double y = 0.0;                      ///< [m]
  double theta = 0.0;                  ///< [rad]
  std::array<double, 9> covariance{};  ///< row-major (x, y, theta) [m^2, m rad, rad^2]
  std::string status;
  int reflectors_used = 0;
};

/// NAV_GOAL (nav_goal_t): its waypoints (x [m], y [m], theta [rad]).
struct ConsoleGoal {
  int64_t goal_id = 0;
  std::vector<std::array<double, 3>> waypoints;
};

struct ConsoleNavStatus {
  int64_t goal_id = 0;
  std::string state;
  int waypoint_index = 0;
  int waypoints_reached = 0;
  int waypoints = 0;
  double distance_to_waypoint = 0.0;  ///< [m]
  double heading_error = 0.0;         ///< [rad]
  std::string reason;
};

struct ConsoleHeartbeat {
  int64_t utime = 0;  ///< [us]
  std::string service;
  int pid = 0;
  std::string state;
  std::string detail;
  double uptime_s = 0.0;  ///< [s]
  int64_t messages_in = 0;
  int64_t messages_out = 0;
  int64_t decode_errors = 0;
  double processing_p50_us = 0.0;  ///< [us]
  double processing_p99_us = 0.0;  ///< [us]
  std::vector<std::pair<std::string, int64_t>> counters;
};

struct ConsoleReflectorHealth {
  int id = 0;
  std::string state;
  int seen = 0;
  int expected_missing = 0;
  double offset_x = 0.0;  ///< [m]
  double offset_y = 0.0;  ///< [m]
};

struct ConsoleCandidate {
  double x = 0.0;  ///< [m]
  double y = 0.0;  ///< [m]
  int sightings = 0;
  int moved_reflector_id = -1;
};

struct ConsoleMapHealth {
  std::string map_id;
  int map_version = 0;
  int64_t scans_used = 0;
  std::vector<ConsoleReflectorHealth> reflectors;
  std::vector<ConsoleCandidate> candidates;
};

}  // namespace refloc
