#include "reflector_matcher/map_health_config.hpp"

#include "common/json_config.hpp"

namespace refloc {
namespace {

int count(const JsonConfig& c, const ConfigKey& key, int value, int min, int max) {
  return static_cast<int>(c.integer(key, value, min, max));
}

void parse_expectation(const JsonConfig& c, MapHealthConfig& m) {
  m.expect_max_range =
      c.number({"/map_health/expect_max_range_m", "m",
                "a map reflector farther from the laser is not expected in a scan (neither "
                "seen nor missing): far cylinders span too few beams to be detected reliably"},
               m.expect_max_range, 0.5, 100.0);
  m.line_of_sight_tolerance = c.number(
      {"/map_health/line_of_sight_tolerance_m", "m",
       "a beam toward an expected reflector ending more than this short of its near face hit something in "
       "front (rack, person): the reflector is hidden and its absence is no evidence"},
      m.line_of_sight_tolerance, 0.0, 5.0);
  m.window_expectations = count(c,
                                {"/map_health/window_expectations", "count",
                                 "per reflector, the last N scans that expected it form the evidence window"},
                                m.window_expectations, 10, 100000);
  m.min_expectations =
      count(c,
            {"/map_health/min_expectations", "count",
             "a reflector expected fewer times in its window cannot be missing yet (state unconfirmed)"},
            m.min_expectations, 1, 100000);
  if (m.min_expectations > m.window_expectations)
    c.fail("/map_health/min_expectations", "must not exceed /map_health/window_expectations");
  m.missing_max_seen_fraction = c.number({"/map_health/missing_max_seen_fraction", "",
                                          "missing when seen in at most this fraction of its window's "
                                          "expectations (a stray match is tolerated)"},
                                         m.missing_max_seen_fraction, 0.0, 0.5);
  m.missing_min_viewpoint_spread = c.number(
      {"/map_health/missing_min_viewpoint_spread_m", "m",
       "and the laser positions it went unseen from since its last sighting span at least this much"},
      m.missing_min_viewpoint_spread, 0.0, 100.0);
}

void parse_moved(const JsonConfig& c, MapHealthConfig& m) {
  m.consistent_fit_rms = c.positive_number(
      {"/map_health/consistent_fit_rms_m", "m",
       "a reflector's offset counts only when the scan's other matches, fitted without it, agree within this "
       "RMS (a moved reflector among them would spoil every other's offset)"},
      m.consistent_fit_rms, 1.0, "0 would refuse every scan");
  m.window_sightings = count(c,
                             {"/map_health/window_sightings", "count",
                              "per reflector, the offsets of its last N sightings are averaged"},
                             m.window_sightings, 2, 100000);
  m.min_sightings = count(c,
                          {"/map_health/min_sightings", "count",
                           "a reflector seen fewer times in its window is unconfirmed, not ok"},
                          m.min_sightings, 1, 100000);
  m.min_offset_sightings = count(c,
                                 {"/map_health/min_offset_sightings", "count",
                                  "offset estimates (scans with >= 4 matches that agree without it) needed "
                                  "before a reflector can be called moved, or ok"},
                                 m.min_offset_sightings, 2, 100000);
  if (m.min_offset_sightings > m.window_sightings)
    c.fail("/map_health/min_offset_sightings", "must not exceed /map_health/window_sightings");
  m.moved_min_offset = c.number({"/map_health/moved_min_offset_m", "m",
                                 "a mean offset between sighting and map smaller than this is no move"},
                                m.moved_min_offset, 0.0, 10.0);
  m.moved_sigma_factor = c.number({"/map_health/moved_sigma_factor", "",
                                   "and the mean offset must exceed this many of its std devs (Mahalanobis)"},
                                  m.moved_sigma_factor, 0.0, 100.0);
  m.offset_sigma_floor = c.positive_number(
      {"/map_health/offset_sigma_floor_m", "m",
       "std dev added to every offset and candidate position estimate: the localized pose's own error"},
      m.offset_sigma_floor, 1.0, "0 would claim the averaged sightings are exact");
}

void parse_candidates(const JsonConfig& c, MapHealthConfig& m) {
  m.candidate_gate = c.positive_number(
      {"/map_health/candidate_gate_m", "m",
       "an unmapped detection (map frame) joins the nearest cluster of unmapped sightings within this"},
      m.candidate_gate, 5.0, "0 would make every sighting its own cluster");
  m.candidate_min_sightings = count(c,
                                    {"/map_health/candidate_min_sightings", "count",
                                     "sightings before a cluster of unmapped detections is a candidate"},
                                    m.candidate_min_sightings, 2, 1000000);
  m.candidate_min_viewpoint_spread = c.number({"/map_health/candidate_min_viewpoint_spread_m", "m",
                                               "and the laser positions it was seen from span at least this"},
                                              m.candidate_min_viewpoint_spread, 0.0, 100.0);
  m.candidate_min_view_angle =
      c.number({"/map_health/candidate_min_view_angle_deg", "deg",
                "and from directions this far apart as seen from the cluster, so the face test "
                "(candidate_radius_m) can tell a cylinder from a flat face"},
               m.candidate_min_view_angle * 180.0 / M_PI, 0.0, 180.0) *
      M_PI / 180.0;
  m.candidate_radius = c.positive_number(
      {"/map_health/candidate_radius_m", "m",
       "radius assumed for an unmapped reflector: centres moved this far toward the laser scatter more "
       "than the centres for a cylinder, less for a flat face whose fitted centre follows the line of sight"},
      m.candidate_radius, 5.0, "0 could not tell a strip from a cylinder");
  m.candidate_max_scatter = c.positive_number(
      {"/map_health/candidate_max_scatter_m", "m",
       "a cluster whose last 64 sightings scatter more (robust std dev: median distance from their "
       "median / 1.18) is no single fixed reflector"},
      m.candidate_max_scatter, 1.0, "0 would refuse every candidate");
  m.max_clusters = count(c,
                         {"/map_health/max_clusters", "count",
                          "clusters of unmapped sightings kept at once; when full the stalest non-candidate "
                          "is forgotten"},
                         m.max_clusters, 1, 100000);
  m.moved_candidate_radius = c.number({"/map_health/moved_candidate_radius_m", "m",
                                       "a missing reflector with a candidate within this of its mapped place "
                                       "is reported moved there (not missing + new)"},
                                      m.moved_candidate_radius, 0.0, 100.0);
  m.moved_min_view_angle =
      c.number(
          {"/map_health/moved_min_view_angle_deg", "deg",
           "a cluster within moved_candidate_radius_m of a missing reflector is its new place once it "
           "has the candidate's sightings, viewpoint spread and scatter and was seen from directions this "
           "far apart; the face test is not made (it needs candidate_min_view_angle_deg)"},
          m.moved_min_view_angle * 180.0 / M_PI, 0.0, 180.0) *
      M_PI / 180.0;
}

}  // namespace

MapHealthConfig parse_map_health_config(const JsonConfig& c) {
  MapHealthConfig m;
  m.enabled = c.boolean({"/map_health/enabled", "",
                         "gather evidence of missing, moved and unmapped reflectors while localizing and "
                         "publish it (map_health_t) on /map_health/channel"},
                        m.enabled);
  m.channel =
      c.string({"/map_health/channel", "", "LCM channel of map_health_t, published every publish_period_s"},
               m.channel);
  m.scan_channel = c.string({"/map_health/scan_channel", "",
                             "LCM channel of the laser scans (laser_scan_t): whether an expected reflector's "
                             "line of sight was clear; without them no reflector is ever missing"},
                            m.scan_channel);
  m.publish_period =
      c.number({"/map_health/publish_period_s", "s",
                "MAP_HEALTH is published this often, also when nothing changed (late joiners)"},
               m.publish_period, 0.05, 60.0);
  m.require_fused_prior =
      c.boolean({"/map_health/require_fused_prior", "",
                 "gather evidence only from OK scans tracked from a fresh OK POSE (odometry "
                 "and laser agree): a wrong OK that the fusion gates out adds nothing"},
                m.require_fused_prior);
  parse_expectation(c, m);
  parse_moved(c, m);
  parse_candidates(c, m);
  return m;
}

}  // namespace refloc
