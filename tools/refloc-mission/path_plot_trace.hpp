#pragma once
// What a picture of a mission needs, as a CSV beside the run's log: the true path, the fused
// POSE and the LASER_POSE fixes with each one's error against the truth at its stamp, and the
// waypoints with when and how well they were reached. tools/refloc-plot draws it (also later,
// from a finished run); the errors come from here so the plot and the report agree.

#include "common/se2.hpp"

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace refloc {

struct TraceSample {
  std::string channel;  ///< GROUND_TRUTH, POSE or LASER_POSE
  int64_t utime = 0;    ///< the message's stamp [us]
  Pose2 map_T_robot;
  double error_m =
      NAN;  ///< distance to GROUND_TRUTH interpolated at utime; NaN: no truth then (or the truth itself)
};

struct TraceWaypoint {
  Pose2 target;
  bool reached = false;
  int64_t reached_utime = 0;  ///< stamp of the truth when the navigator reported it [us]
  double error_m = NAN;       ///< true arrival error [m]
};

struct PathTrace {
  int64_t start_utime = 0;  ///< driving started: t = 0 of the CSV [us]
  std::vector<TraceSample> samples;
  std::vector<TraceWaypoint> waypoints;
};

/// "kind,t_s,x_m,y_m,theta_rad,error_mm" and a row per sample (kind = channel) and per
/// waypoint (kind WAYPOINT: the target; t_s its arrival, error_mm its true arrival error, both
/// empty when not reached). t_s counts from start_utime; error_mm is empty where unknown.
std::string path_trace_csv(const PathTrace& trace);

/// Writes path_trace_csv(trace) to path; false when the file cannot be written.
bool write_path_trace_csv(const std::string& path, const PathTrace& trace);

}  // namespace refloc
