#include "reflector_matcher/matcher_config_file.hpp"

#include "common/json_config.hpp"

#include <filesystem>

namespace refloc {

MatcherServiceConfig parse_matcher_service_config(const JsonConfig& config, const std::string& base_dir) {
  MatcherServiceConfig s;
  MatcherConfig& m = s.matcher;
  constexpr double kDeg = M_PI / 180.0;
  const std::string map_name = config.string({"/map_file", "",
                                              "the reflector map (JSON); a relative path is read from this "
                                              "config file's folder; --map overrides it"},
                                             "map_demo.json");
  std::filesystem::path map_path(map_name);
  if (map_path.is_relative() && !base_dir.empty()) map_path = std::filesystem::path(base_dir) / map_path;
  s.map_file = map_path.lexically_normal().string();
  m.mode = config.choice({"/mode", "",
                          "default: tracking from a prior, else indexed triangles verified against the whole "
                          "scan; paper: the §3.5 triangle votes (unverified baseline)"},
                         "default", {"default", "paper"}) == "paper"
               ? MatcherMode::kPaper
               : MatcherMode::kDefault;
  s.input_channel = config.string(
      {"/input_channel", "", "LCM channel of the detections read (reflector_detections_t)"}, s.input_channel);
  s.prior_channel = config.string(
      {"/prior_channel", "",
       "LCM channel of the fused robot pose (pose2d_t): the tracking prior when its status is OK"},
      s.prior_channel);
  s.initial_pose_channel = config.string(
      {"/initial_pose_channel", "",
       "LCM channel of a user's \"the robot is here\" (pose2d_t, e.g. from web_console): a prior, verified"},
      s.initial_pose_channel);
  s.output_channel = config.string(
      {"/output_channel", "",
       "LCM channel the matches are published on (reflector_matches_t), one message per accepted scan"},
      s.output_channel);
  PriorSelectionConfig& p = s.prior;
  p.max_age = config.number({"/prior_max_age_s", "s",
                             "a POSE or own last OK pose further than this from the scan (either side) is no "
                             "prior: global relocalization instead"},
                            p.max_age, 0.0, 10.0);
  p.use_own_pose = config.boolean({"/use_own_pose_as_prior", "",
                                   "without a fresh POSE, track from the matcher's own last OK pose "
                                   "(own_prior_sigma_*); false: relocalize from the map instead"},
                                  p.use_own_pose);
  p.own_sigma_xy = config.number({"/own_prior_sigma_m", "m",
                                  "position std dev assumed for the own last OK pose as a prior: covers the "
                                  "robot's motion since (up to prior_max_age_s)"},
                                 p.own_sigma_xy, 0.001, 10.0);
  p.own_sigma_theta = config.number({"/own_prior_sigma_deg", "deg",
                                     "heading std dev assumed for the own last OK pose as a prior"},
                                    p.own_sigma_theta / kDeg, 0.01, 90.0) *
                      kDeg;
  p.relocalize_on_start = config.number({"/relocalize_on_start_s", "s",
                                         "after start, ignore priors until a global relocalization is OK, "
                                         "for at most this long (then trust POSE again); 0: track at once"},
                                        p.relocalize_on_start, 0.0, 60.0);
  p.initial_pose_hold =
      config.number({"/initial_pose_hold_s", "s",
                     "an INITIAL_POSE is the prior for this long from the next scan; once a "
                     "scan matches from it, the own poses are preferred to POSE for as long"},
                    p.initial_pose_hold, 0.1, 60.0);

  m.sensor.min_range =
      config.number({"/sensor/min_range_m", "m",
                     "map reflectors nearer than this are not expected in a scan (tracking, verification)"},
                    m.sensor.min_range, 0.0, 100.0);
  m.sensor.max_range = config.number(
      {"/sensor/max_range_m", "m",
       "map reflectors farther are not expected in a scan; the default max triangle side is twice this"},
      m.sensor.max_range, 0.5, 100.0);
  m.sensor.field_of_view = config.number({"/sensor/field_of_view_deg", "deg",
                                          "the scanner's full opening angle, centred on the laser's +x: "
                                          "reflectors outside it are not expected"},
                                         m.sensor.field_of_view / kDeg, 1.0, 360.0) *
                           kDeg;
  if (m.sensor.min_range >= m.sensor.max_range)
    config.fail("/sensor/min_range_m", "must be below /sensor/max_range_m");

  m.paper.side_tolerance = config.number({"/paper/side_tolerance_m", "m",
                                          "paper mode: the two sides next to a detection triangle's largest "
                                          "angle must match a map triangle's within this"},
                                         m.paper.side_tolerance, 0.001, 2.0);
  m.paper.angle_tolerance =
      config.number({"/paper/angle_tolerance_deg", "deg", "paper mode: and its largest angle within this"},
                    m.paper.angle_tolerance / kDeg, 0.01, 45.0) *
      kDeg;

  m.tracking.prior_min_sigma_xy = config.number({"/tracking/prior_min_sigma_m", "m",
                                                 "floor on the prior's position std dev in the gate: a prior "
                                                 "claiming more certainty is widened to this"},
                                                m.tracking.prior_min_sigma_xy, 0.0, 10.0);
  m.tracking.prior_min_sigma_theta = config.number({"/tracking/prior_min_sigma_deg", "deg",
                                                    "floor on the prior's heading std dev in the gate"},
                                                   m.tracking.prior_min_sigma_theta / kDeg, 0.0, 90.0) *
                                     kDeg;
  m.tracking.gate_chi2 = config.number({"/tracking/gate_chi2", "",
                                        "Mahalanobis^2 gate pairing a detection with a predicted reflector "
                                        "(13.8 = 99.9 % for 2 dof); larger admits farther pairs"},
                                       m.tracking.gate_chi2, 0.1, 1000.0);
  m.tracking.detection_min_sigma = config.positive_number(
      {"/tracking/detection_min_sigma_m", "m",
       "std dev added to each detection's covariance in the gate, so an over-confident detection is not "
       "gated out"},
      m.tracking.detection_min_sigma, 1.0, "0 lets an exact detection divide the gate by zero");
  m.tracking.max_unexplained =
      static_cast<int>(config.integer({"/tracking/max_unexplained", "count",
                                       "a tracked association leaving more detections unexplained is checked "
                                       "by global relocalization (the prior may be off)"},
                                      m.tracking.max_unexplained, 0, 1000));
  m.tracking.min_score = config.number(
      {"/tracking/min_score", "",
       "the same when the tracked pose's verification score (matched - penalties) is below this"},
      m.tracking.min_score, -1000.0, 1000.0);
  m.tracking.bare_overrule_confirm_scans = static_cast<int>(config.integer(
      {"/tracking/bare_overrule_confirm_scans", "count",
       "when tracking from a prior fails and relocalization finds a pose elsewhere on the bare minimum of "
       "pairs, another scan within this many must find the same pose before it is a fix (AMBIGUOUS until "
       "then); 0: off"},
      m.tracking.bare_overrule_confirm_scans, 0, 1000));

  m.relocalization.side_tolerance = config.number({"/relocalization/side_tolerance_m", "m",
                                                   "per sorted side when looking a detection triangle up in "
                                                   "the map index; larger: more candidates, slower"},
                                                  m.relocalization.side_tolerance, 0.001, 2.0);
  m.relocalization.side_tolerance_sigmas =
      config.number({"/relocalization/side_tolerance_sigmas", "-",
                     "a side also agrees within this many of its own standard deviations (its two "
                     "detections' covariances along it), added to side_tolerance_m in quadrature; a pose "
                     "found only so is a rival (AMBIGUOUS), never the answer; 0: side_tolerance_m alone"},
                    m.relocalization.side_tolerance_sigmas, 0.0, 10.0);
  m.relocalization.max_side_tolerance =
      config.number({"/relocalization/max_side_tolerance_m", "m",
                     "cap on the tolerance side_tolerance_sigmas widens (bounds the lookup's cost)"},
                    m.relocalization.max_side_tolerance, 0.001, 2.0);
  if (m.relocalization.max_side_tolerance < m.relocalization.side_tolerance) {
    config.fail("/relocalization/max_side_tolerance_m", "must be at least /relocalization/side_tolerance_m");
  }
  m.relocalization.min_triangle_side =
      config.number({"/relocalization/min_triangle_side_m", "m",
                     "triangles with a shorter side are not used for relocalization (poor heading)"},
                    m.relocalization.min_triangle_side, 0.0, 50.0);
  m.relocalization.max_triangle_side =
      config.number({"/relocalization/max_triangle_side_m", "m",
                     "longest triangle side indexed (also paper mode); default 2 x sensor/max_range_m; "
                     "shrunk to fit max_index_triangles"},
                    2.0 * m.sensor.max_range, 0.1, 1000.0);
  if (m.relocalization.max_triangle_side <= m.relocalization.min_triangle_side) {
    config.fail("/relocalization/max_triangle_side_m",
                "must be above /relocalization/min_triangle_side_m (else no triangle is indexed)");
  }
  m.relocalization.max_index_triangles =
      static_cast<int>(config.integer({"/relocalization/max_index_triangles", "count",
                                       "cap on the map triangle index (memory, start time): "
                                       "max_triangle_side_m shrinks by 20 % steps until it fits"},
                                      m.relocalization.max_index_triangles, 1000, 100000000));
  m.relocalization.max_triple_detections = static_cast<int>(
      config.integer({"/relocalization/max_triple_detections", "count",
                      "only the nearest N detections form triangles (N(N-1)(N-2)/6 looked up per scan)"},
                     m.relocalization.max_triple_detections, 3, 100));
  m.relocalization.max_hypotheses = static_cast<int>(
      config.integer({"/relocalization/max_hypotheses", "count",
                      "pose hypotheses per scan at most: bounds the relocalization time (the "
                      "rivals only side_tolerance_sigmas finds: as many again)"},
                     m.relocalization.max_hypotheses, 1, 10000000));
  m.relocalization.hypothesis_fit_max_error = config.number(
      {"/relocalization/hypothesis_fit_max_error_m", "m",
       "a triangle whose rigid fit onto the map triangle leaves a larger error is no hypothesis"},
      m.relocalization.hypothesis_fit_max_error, 0.001, 5.0);
  m.relocalization.verify_coarse_gate = config.number(
      {"/relocalization/verify_coarse_gate_m", "m",
       "association radius of a first check of a hypothesis against the map reflectors predicted in view"},
      m.relocalization.verify_coarse_gate, 0.001, 5.0);
  m.relocalization.verify_fine_gate = config.number(
      {"/relocalization/verify_fine_gate_m", "m",
       "association radius after refitting with the coarse pairs: detections within it count as matched"},
      m.relocalization.verify_fine_gate, 0.001, 5.0);
  m.relocalization.missed_penalty =
      config.number({"/relocalization/missed_penalty", "",
                     "score lost per map reflector expected in view (unshadowed, within "
                     "missed_penalty_max_range_m) but not detected"},
                    m.relocalization.missed_penalty, 0.0, 10.0);
  m.relocalization.missed_penalty_max_range = config.number(
      {"/relocalization/missed_penalty_max_range_m", "m",
       "reflectors farther cost nothing when unseen (beyond ~7 m a 120 mm cylinder spans < 2 beams)"},
      m.relocalization.missed_penalty_max_range, 0.0, 100.0);
  m.relocalization.unexplained_penalty = config.number(
      {"/relocalization/unexplained_penalty", "", "score lost per detection no map reflector explains"},
      m.relocalization.unexplained_penalty, 0.0, 10.0);
  m.relocalization.fit_consistency_sigmas = config.number(
      {"/relocalization/fit_consistency_sigmas", "",
       "the matched pairs' residuals after the rigid fit (chi-square with the detections' covariance and "
       "map_sigma_m) may exceed the chi-square's mean by this many standard deviations; worse pairs "
       "are dropped while 4 remain, a 3-pair match that still fails explains nothing (two reflectors "
       "moved 0.3 m matched as if in place); 0: off"},
      m.relocalization.fit_consistency_sigmas, 0.0, 100.0);
  m.relocalization.map_sigma = config.number(
      {"/relocalization/map_sigma_m", "m",
       "position uncertainty of a map reflector without a survey covariance (the consistency test)"},
      m.relocalization.map_sigma, 0.0, 1.0);
  m.relocalization.range_bias_sigma = config.number(
      {"/relocalization/range_bias_sigma_m", "m",
       "extra error the consistency test allows along each detection's line of sight: the sensor's "
       "systematic range error (LMS100: up to +-30 mm), which pose_solver, not the matcher, estimates"},
      m.relocalization.range_bias_sigma, 0.0, 1.0);
  m.relocalization.min_explained_fraction =
      config.number({"/relocalization/min_explained_fraction", "",
                     "a global OK, and a kept tracked association, must explain at least this fraction of "
                     "the detections; else LOST"},
                    m.relocalization.min_explained_fraction, 0.0, 1.0);
  m.relocalization.min_score = config.number({"/relocalization/min_score", "",
                                              "a global hypothesis scoring less is no fix; -1000: off (2.0 "
                                              "removes rare wrong fixes but costs 16 % of the fixes)"},
                                             m.relocalization.min_score, -1000.0, 1000.0);
  m.relocalization.ambiguity_ratio = config.number({"/relocalization/ambiguity_ratio", "",
                                                    "AMBIGUOUS when a distinct pose scores within (1 - "
                                                    "ratio) x (detections the best explains) of the best"},
                                                   m.relocalization.ambiguity_ratio, 0.0, 1.0);
  m.relocalization.ambiguity_missed_margin =
      config.number({"/relocalization/ambiguity_missed_margin", "",
                     "a distinct pose explaining as many detections is a rival unless the best scores this "
                     "much higher (0.5 per unseen reflector)"},
                    m.relocalization.ambiguity_missed_margin, 0.0, 100.0);
  m.relocalization.ambiguity_max_margin = config.number(
      {"/relocalization/ambiguity_max_margin", "",
       "caps (1 - ambiguity_ratio) x explained: a pose scoring this much below the best is no "
       "rival however many detections are seen (1.25 = one detection the rival cannot explain)"},
      m.relocalization.ambiguity_max_margin, 0.0, 100.0);
  m.relocalization.distinct_pose_distance =
      config.number({"/relocalization/distinct_pose_distance_m", "m",
                     "a pose farther than this from the best (or turned by more than "
                     "distinct_pose_angle_deg) is a distinct pose, a rival"},
                    m.relocalization.distinct_pose_distance, 0.0, 100.0);
  m.relocalization.distinct_pose_angle =
      config.number({"/relocalization/distinct_pose_angle_deg", "deg",
                     "the heading difference that makes a pose distinct from the best"},
                    m.relocalization.distinct_pose_angle / kDeg, 0.0, 180.0) *
      kDeg;
  m.min_matches = static_cast<int>(config.integer(
      {"/min_matches", "count",
       "fewer explained detections: LOST, no fix (3 is the fewest a 2D pose can be checked with)"},
      m.min_matches, 3, 100));
  s.map_health = parse_map_health_config(config);
  return s;
}

MatcherServiceConfig load_matcher_service_config(const std::string& path) {
  const JsonConfig file =
      path.empty() ? JsonConfig(nlohmann::json::object(), "(defaults)") : JsonConfig::load_file(path);
  const std::string base =
      path.empty() ? "deploy/config" : std::filesystem::path(path).parent_path().string();
  MatcherServiceConfig config = parse_matcher_service_config(file, base);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
