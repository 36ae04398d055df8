#pragma once
// Settings of the reflector matcher, one struct a section of reflector_matcher.json
// ("sensor", "paper", "tracking", "relocalization"); defaults suit an LMS100 seeing 120 mm
// reflectors.

#include <cmath>

namespace refloc {

enum class MatcherMode {
  kPaper,    ///< §3.5: largest-angle triangle signatures compared with every map triangle
  kDefault,  ///< tracking from a prior, else indexed triangle votes + whole-scan verification
};

/// "sensor": what a map reflector must satisfy to be expected in the scan.
struct SensorVisibilityConfig {
  double min_range = 0.3;                       ///< min_range_m [m]
  double max_range = 20.0;                      ///< max_range_m: reflectors farther are not expected [m]
  double field_of_view = 270.0 * M_PI / 180.0;  ///< field_of_view_deg: full opening angle [rad]
};

/// "paper" (§3.5).
struct PaperMatchingConfig {
  double side_tolerance = 0.05;                 ///< side_tolerance_m: on each adjacent side [m]
  double angle_tolerance = 2.0 * M_PI / 180.0;  ///< angle_tolerance_deg: on the largest angle [rad]
};

/// "tracking": association from a prior.
struct TrackingConfig {
  double prior_min_sigma_xy = 0.05;                   ///< prior_min_sigma_m: floor of the prior's std dev [m]
  double prior_min_sigma_theta = 1.0 * M_PI / 180.0;  ///< prior_min_sigma_deg [rad]
  double gate_chi2 = 13.8;                            ///< Mahalanobis^2 gate, 2 dof 99.9 % [-]
  double detection_min_sigma = 0.005;  ///< detection_min_sigma_m: floor of a detection's std dev [m]
  /// max_unexplained: a tracked association leaving more detections unexplained than this is
  /// checked by global relocalization: a prior that is off (kidnapped robot, odometry jump)
  /// can line three detections up with the wrong reflectors and leave the rest unexplained [-].
  int max_unexplained = 1;
  /// min_score: same when the tracked pose's verification score is below this (score as in
  /// missed_penalty): three wrong pairs near a wrong prior leave the reflectors really in view
  /// unexplained or "missing" [-].
  double min_score = 2.0;
  /// bare_overrule_confirm_scans: when tracking from a prior fails and the map-wide search finds
  /// an OK pose elsewhere on the bare minimum of pairs, that pose is a fix only once another scan
  /// within this many gives the same pose (until then AMBIGUOUS). A triangle that fits the map at
  /// a second place fools one scan; a kidnapped robot sees its new place in every scan. 0: off [count].
  int bare_overrule_confirm_scans = 5;
};

/// "relocalization": global relocalization and the verification of a hypothesis.
struct RelocalizationConfig {
  double side_tolerance = 0.08;       ///< side_tolerance_m: per sorted side when looking up map triangles [m]
  double min_triangle_side = 0.3;     ///< min_triangle_side_m: shorter sides give poor headings [m]
  double max_triangle_side = 40.0;    ///< max_triangle_side_m: triangles a scan can see, 2 * max range [m]
  int max_index_triangles = 5000000;  ///< cap on the index size; max_triangle_side shrinks to meet it
  /// side_tolerance_sigmas: a scan triangle's side also agrees with a map side within this many
  /// of its own standard deviations (its two detections' covariances along it), added to
  /// side_tolerance in quadrature. Far 2-beam detections are 10-20 mm uncertain across the beam:
  /// the true triangle once missed the fixed 80 mm by 0.5 mm while a wrong one 10 m away fitted,
  /// and that scan published a wrong fix from scratch. A pose found only through the wider
  /// tolerance is a rival (AMBIGUOUS), never the answer. 0 = side_tolerance alone [-].
  double side_tolerance_sigmas = 2.0;
  double max_side_tolerance = 0.16;  ///< max_side_tolerance_m: cap on that wider tolerance (cost) [m]
  int max_triple_detections = 20;    ///< only the nearest N detections form triples
  /// per scan, bounds the relocalization time; the rivals only the widened tolerance finds have
  /// a cap of the same size of their own
  int max_hypotheses = 4000;
  double hypothesis_fit_max_error = 0.15;  ///< _m: a triangle whose rigid fit is worse is no hypothesis [m]
  double verify_coarse_gate = 0.5;         ///< verify_coarse_gate_m: first association of a hypothesis [m]
  double verify_fine_gate = 0.15;  ///< verify_fine_gate_m: after refitting with all coarse matches [m]
  double missed_penalty = 0.5;     ///< score lost per expected, unoccluded, unseen reflector [-]
  /// missed_penalty_max_range_m: reflectors farther are not expected to be detected: at 0.5 deg
  /// a 120 mm cylinder spans fewer than 2 beams beyond ~7 m, which the extractor may reject [m].
  double missed_penalty_max_range = 8.0;
  double unexplained_penalty = 0.25;  ///< score lost per detection no map reflector explains [-]
  /// fit_consistency_sigmas: the pairs' residuals after the rigid fit, as a chi-square with the
  /// detections' covariances (+ map_sigma), may exceed its mean by at most this many of its
  /// standard deviations (Wilson-Hilferty); worse pairs are dropped while 4 or more remain,
  /// and a 3-pair hypothesis that still fails explains nothing. 0 = off [-].
  double fit_consistency_sigmas = 3.5;
  /// map_sigma_m: position uncertainty of a map reflector without a survey covariance [m]
  double map_sigma = 0.005;
  /// range_bias_sigma_m: the test allows each detection this much more error along its line
  /// of sight: the LMS100's systematic range error (SICK: up to +-30 mm), which the matcher does
  /// not estimate (pose_solver does) [m]
  double range_bias_sigma = 0.03;
  double min_explained_fraction = 0.6;  ///< of the detections, for a global OK [-]
  /// min_score: a global hypothesis scoring less is no fix [-]. Off by default (-1000): a floor
  /// of 2.0 removed the rare wrong OK from scratch (1 in 40,000 rendered demo-hall scans) but
  /// also 16 % of the fixes, and left spots of the demo hall (few reflectors, racks hiding
  /// others) where a lost robot could never relocalize.
  double min_score = -1000.0;
  /// AMBIGUOUS when best - runner-up < (1 - ratio) * (detections the best explains): with no
  /// penalties this is runner-up >= ratio * best [-].
  double ambiguity_ratio = 0.8;
  /// A pose explaining as many detections as the best is a rival unless the best scores at
  /// least this much higher (0.5 per unseen reflector: 2.0 = four more unseen) [-].
  double ambiguity_missed_margin = 2.0;
  /// Caps the first rule's (1 - ratio) x explained: a pose scoring at least this much below the
  /// best is no rival however many detections the best explains. One detection the best
  /// explains and the rival cannot is worth 1.25 (1 + unexplained_penalty) whether 4 or 12
  /// reflectors are in view; a larger view does not make that evidence weaker. Below 1.25 it
  /// changes only views of 7 or more explained detections (README, "The rival rule's cap") [-].
  double ambiguity_max_margin = 1.2;
  double distinct_pose_distance = 0.2;  ///< _m: a runner-up must differ at least this much ... [m]
  double distinct_pose_angle = 5.0 * M_PI / 180.0;  ///< _deg: ... or this much from the best [rad]
};

/// The file's "mode", "min_matches" and sections (the prior keys: PriorSelectionConfig).
struct MatcherConfig {
  MatcherMode mode = MatcherMode::kDefault;
  int min_matches = 3;  ///< fewer explained detections -> LOST
  SensorVisibilityConfig sensor;
  PaperMatchingConfig paper;
  TrackingConfig tracking;
  RelocalizationConfig relocalization;
};

}  // namespace refloc
