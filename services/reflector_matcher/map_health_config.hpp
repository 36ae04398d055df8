#pragma once
// The "map_health" section of reflector_matcher.json: when the matcher's evidence says a map
// reflector is missing or moved, or an unmapped one is a candidate (map_evidence.hpp), and
// where MAP_HEALTH is published.

#include <cmath>
#include <string>

namespace refloc {

class JsonConfig;

struct MapHealthConfig {
  bool enabled = true;                       ///< enabled: gather evidence, publish MAP_HEALTH
  std::string channel = "MAP_HEALTH";        ///< channel: map_health_t out
  std::string scan_channel = "LMS100_SCAN";  ///< scan_channel: laser_scan_t in (line of sight)
  double publish_period = 1.0;               ///< publish_period_s [s]
  /// require_fused_prior: use only OK scans tracked from a fresh OK POSE, i.e. where odometry
  /// and the laser agree; a wrong OK the fusion gates out then leaves no false evidence.
  bool require_fused_prior = true;

  /// expect_max_range_m: a reflector farther is not expected. Demo mission, in clear sight: matched
  /// in 94-97 % of the scans within 1-5 m, 76 % at 5-6 m, 58 % at 6-7 m, 28 % at 7-8 m [m].
  double expect_max_range = 5.0;
  /// line_of_sight_tolerance_m: a beam ending more than this short of the reflector's near face
  /// hit something in front of it (a rack, a person): hidden, no evidence either way [m].
  double line_of_sight_tolerance = 0.15;
  int window_expectations = 250;            ///< per reflector, the last N times it was expected [count]
  int min_expectations = 50;                ///< fewer in the window: not yet missing (unconfirmed) [count]
  double missing_max_seen_fraction = 0.05;  ///< seen in at most this fraction of the window: missing [-]
  /// missing_min_viewpoint_spread_m: and the laser positions it went unseen from since it was
  /// last seen span at least this: one spot can hide it behind something the scan cannot tell [m].
  double missing_min_viewpoint_spread = 0.5;

  /// consistent_fit_rms_m: a scan's matches fitted without one reflector must agree within this
  /// RMS for that reflector's offset to count (so a moved one among them spoils no other's),
  /// and the scan's unmapped detections are placed with the best such fit [m].
  double consistent_fit_rms = 0.02;
  int window_sightings = 100;  ///< offsets of the last N sightings per reflector [count]
  int min_sightings = 10;      ///< fewer: unconfirmed rather than ok [count]
  /// min_offset_sightings: offset estimates needed to call a reflector moved, or ok [count]
  int min_offset_sightings = 10;
  double moved_min_offset = 0.05;     ///< moved_min_offset_m: a smaller mean offset is not a move [m]
  double moved_sigma_factor = 3.0;    ///< and it must exceed this many of its own std devs [-]
  double offset_sigma_floor = 0.005;  ///< offset_sigma_floor_m: added to every std dev (pose error) [m]

  double candidate_gate = 0.15;  ///< candidate_gate_m: an unmapped detection joins a cluster this near [m]
  int candidate_min_sightings = 25;             ///< sightings before a cluster is a candidate [count]
  double candidate_min_viewpoint_spread = 0.5;  ///< _m: seen from laser positions this far apart [m]
  /// candidate_min_view_angle_deg: and from directions (seen from the candidate) this far apart,
  /// so the face test (fronts in map_evidence.hpp) can tell a cylinder from a flat face [rad].
  double candidate_min_view_angle = 20.0 * M_PI / 180.0;
  double candidate_radius = 0.06;  ///< candidate_radius_m: the radius new reflectors are assumed to have [m]
  /// candidate_max_scatter_m: a cluster whose last 64 sightings scatter more (robust std dev)
  /// is no single fixed reflector [m]. Tape narrower than a cylinder's diameter does not scatter:
  /// the known-radius circle fitted to a straight strip sits on the strip's perpendicular bisector
  /// from any viewpoint; only the map's occluders (a centre behind a face) reject it.
  double candidate_max_scatter = 0.02;
  int max_clusters = 256;  ///< unmapped clusters kept; the stalest goes first [count]
  double moved_candidate_radius =
      1.0;  ///< _m: a missing reflector with a candidate this near moved there [m]
  /// moved_min_view_angle_deg: a cluster near a missing reflector is its new place when seen
  /// from directions this far apart (the other candidate rules hold, the face test is not made):
  /// driving straight at a moved reflector turns the view by a few degrees in 10 s [rad].
  double moved_min_view_angle = 0.0;
};

/// Reads and validates "/map_health/..." of the matcher's file.
MapHealthConfig parse_map_health_config(const JsonConfig& config);

}  // namespace refloc
