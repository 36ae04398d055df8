#include "reflector_extractor/extractor_config_file.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {

ExtractorServiceConfig parse_extractor_service_config(const JsonConfig& c) {
  ExtractorServiceConfig out;
  const std::string mode =
      c.choice({"/mode", "",
                "default: known-radius fit with covariance and shape tests; paper: the paper's §3.2-3.4 "
                "baseline (its defaults: min_beams 3, max_gap_beams -1)"},
               "default", {"default", "paper"});
  ExtractorConfig& e = out.extractor;
  e = mode == "paper" ? ExtractorConfig::paper() : ExtractorConfig{};

  out.input_channel = c.string({"/input_channel", "", "LCM channel of the laser scans read (laser_scan_t)"},
                               out.input_channel);
  out.output_channel = c.string(
      {"/output_channel", "",
       "LCM channel the detections are published on (reflector_detections_t), one message per accepted scan"},
      out.output_channel);
  out.clusters_channel = c.string(
      {"/clusters_channel", "",
       "LCM channel of every bright cluster with its outcome (accepted, or the reason it was rejected) "
       "and the energy threshold (reflector_clusters_t), one message per accepted scan, for commissioning "
       "views; \"\" publishes none"},
      out.clusters_channel);
  out.odometry_channel =
      c.string({"/odometry_channel", "",
                "LCM channel of the body twist (odometry_t) that motion-compensates the scans"},
               out.odometry_channel);
  out.motion_compensation = c.boolean({"/motion_compensation", "",
                                       "move each detection from its beam's time to the scan's first beam; "
                                       "false: a 15 ms blend of poses (~12 mm at 0.8 m/s)"},
                                      out.motion_compensation);
  out.odometry_max_age = c.number({"/odometry_max_age_s", "s",
                                   "ODOMETRY further than this from the scan (either side) is stale: the "
                                   "fixes' twist (fix_velocity) compensates instead"},
                                  out.odometry_max_age, 0.0, 10.0);
  out.laser_pose_channel = c.string(
      {"/laser_pose_channel", "",
       "LCM channel of the solver's fixes (pose2d_t), the motion source while ODOMETRY is absent or stale"},
      out.laser_pose_channel);
  FixVelocityConfig& f = out.fix_velocity;
  f.enabled = c.boolean({"/fix_velocity/enabled", "",
                         "without fresh ODOMETRY, use the twist fitted to recent OK LASER_POSE fixes; false: "
                         "then nothing compensates"},
                        f.enabled);
  f.window_s = c.positive_number({"/fix_velocity/window_s", "s",
                                  "fixes older than this before the newest are dropped; longer: less noise, "
                                  "more lag behind an acceleration"},
                                 f.window_s, 2.0, "0 would keep no fix to fit");
  f.max_age_s =
      c.number({"/fix_velocity/max_age_s", "s",
                "newest fix further than this from the scan (either side): no twist from the fixes"},
               f.max_age_s, 0.0, 10.0);
  f.min_fixes = static_cast<int>(
      c.integer({"/fix_velocity/min_fixes", "count", "fewer OK fixes in the window: no twist from the fixes"},
                f.min_fixes, 2, 100));
  f.min_span_s = c.positive_number({"/fix_velocity/min_span_s", "s",
                                    "oldest to newest fix in the window must span at least this (<= "
                                    "window_s): shorter spans give noisy slopes"},
                                   f.min_span_s, 2.0, "0 would fit a velocity to fixes at one instant");
  f.max_rms_residual_m =
      c.positive_number({"/fix_velocity/max_rms_residual_m", "m",
                         "fixes scattered more about the fitted line (a bad fix, a wrong match): no twist; "
                         "raise only for noisier fixes"},
                        f.max_rms_residual_m, 1.0, "0 would refuse every fit of noisy fixes");
  if (f.min_span_s > f.window_s)
    c.fail("/fix_velocity/min_span_s",
           fmt::format("{} s is longer than /fix_velocity/window_s {} s: no window "
                       "could ever hold it",
                       f.min_span_s, f.window_s));

  const std::string scale = c.choice({"/rssi_scale", "",
                                      "how a 16-bit RSSI channel is read: auto detects 8-bit values sent in "
                                      "it; native divides by 257; 8bit_in_16bit takes them as they are"},
                                     "auto", {"auto", "native", "8bit_in_16bit"});
  out.rssi_scale.mode = scale == "auto"     ? RssiScaleConfig::Mode::kAuto
                        : scale == "native" ? RssiScaleConfig::Mode::kNative
                                            : RssiScaleConfig::Mode::k8bitIn16bit;
  out.no_reflector_timeout = c.positive_number(
      {"/no_reflector_timeout_s", "s",
       "accepted scans without any reflector for longer than this make the state DEGRADED (with the reason); "
       "raise where reflectors are sparse"},
      out.no_reflector_timeout, 3600.0, "0 would degrade the state on every scan without a reflector");

  e.energy_threshold_8bit =
      c.number({"/energy_threshold_8bit", "8-bit RSSI",
                "echoes at least this bright can be reflector beams; lower if reflectors are missed, raise "
                "if shiny surfaces pass (refloc-calibrate-rssi)"},
               e.energy_threshold_8bit, 0.0, 255.0);
  e.reflector_radius = c.number({"/reflector_radius_m", "m",
                                 "radius of the reflector cylinders, held fixed in every centre fit and "
                                 "shape test; measure yours (120 mm diameter: 0.06)"},
                                e.reflector_radius, 0.005, 1.0);
  e.min_beams =
      static_cast<int>(c.integer({"/min_beams", "count",
                                  "smaller bright clusters are not reflectors; 1 keeps far ones (one beam "
                                  "beyond ~7 m) with no shape test; paper mode needs >= 3"},
                                 e.min_beams, 1, 1000));

  e.clustering.lambda = c.number({"/clustering/lambda_deg", "deg",
                                  "paper eq. 3 auxiliary angle: bright points farther apart than r "
                                  "sin(dphi)/sin(lambda-dphi) + 3 sigma_r split; larger splits sooner"},
                                 e.clustering.lambda / kDegToRad, 1.0, 89.0) *
                        kDegToRad;
  e.clustering.range_sigma =
      c.positive_number({"/clustering/range_sigma_m", "m",
                         "range noise of the sensor: 3 sigma in the breakpoint distance, weight of every "
                         "centre fit, hence the detections' covariance"},
                        e.clustering.range_sigma, 0.5, "0 would split every cluster: nothing detected");
  e.clustering.max_gap_beams =
      static_cast<int>(c.integer({"/clustering/max_gap_beams", "count",
                                  "non-bright beams allowed inside a cluster: 0 splits reflectors side by "
                                  "side; -1 unlimited (the paper's)"},
                                 e.clustering.max_gap_beams, -1, 100));

  e.paper_drop_points =
      static_cast<int>(c.integer({"/paper/drop_points", "count",
                                  "paper mode: first and last n points of a cluster left out of d-bar (and "
                                  "of the polar range): edge beams are partial hits"},
                                 e.paper_drop_points, 0, 20));
  e.paper_roundness.offset = c.number({"/paper/roundness_offset_m", "m",
                                       "paper mode: a cluster is a reflector when d-bar <= offset + slope * "
                                       "range; refloc-calibrate-roundness prints both"},
                                      e.paper_roundness.offset, -1.0, 1.0);
  e.paper_roundness.slope =
      c.number({"/paper/roundness_slope", "m/m",
                "paper mode: slope of that acceptance line per metre of range (refloc-calibrate-roundness)"},
               e.paper_roundness.slope, -1.0, 1.0);
  const std::string centre = c.choice({"/paper/centre", "",
                                       "paper mode: the centre from a cluster: known_radius (designed radius "
                                       "fixed; best), kasa (free circle, ~30 mm short), polar"},
                                      to_string(e.paper_centre), {"known_radius", "kasa", "polar"});
  e.paper_centre = centre == "kasa"    ? PaperCentreReading::kAlgebraicFreeRadius
                   : centre == "polar" ? PaperCentreReading::kPolar
                                       : PaperCentreReading::kKnownRadius;

  e.angle_sigma = c.number({"/default/angle_sigma_rad", "rad",
                            "bearing noise of a beam: adds (range * sigma)^2 across the line of sight to "
                            "each detection's covariance"},
                           e.angle_sigma, 0.0, 0.1);
  e.edge_rssi_ratio = c.number({"/default/edge_rssi_ratio", "",
                                "an edge beam dimmer than this fraction of the cluster's brightest is a "
                                "partial hit: dropped from the fit (one a side at most)"},
                               e.edge_rssi_ratio, 0.0, 1.0);
  e.occlusion_margin = c.number({"/default/occlusion_margin_m", "m",
                                 "a neighbour echo nearer than the cluster's edge by more than this hides "
                                 "part of the reflector (see reject_occluded)"},
                                e.occlusion_margin, 0.0, 10.0);
  e.reject_occluded =
      c.boolean({"/default/reject_occluded", "",
                 "reject clusters partly hidden behind a nearer echo: their centre would be biased sideways"},
                e.reject_occluded);
  e.reject_next_to_dazzled = c.boolean(
      {"/default/reject_next_to_dazzled", "",
       "reject clusters next to a dazzled beam (sensor code 1), which may be the rest of the reflector"},
      e.reject_next_to_dazzled);
  e.fit.max_iterations = static_cast<int>(c.integer(
      {"/default/fit/max_iterations", "count",
       "Gauss-Newton iterations of the centre fits (they stop earlier once the centre moves < 1 um)"},
      e.fit.max_iterations, 1, 100));
  e.fit.min_incidence_cos = c.number({"/default/fit/min_incidence_cos", "",
                                      "floor on cos(incidence) in the fits' residuals: caps the weight of "
                                      "near-grazing beams (0.6 = 53 deg)"},
                                     e.fit.min_incidence_cos, 0.01, 1.0);
  EchoSpotModel& spot = e.fit.spot;
  spot.divergence_rad = c.number({"/default/fit/spot/divergence_rad", "rad",
                                  "full angle of the laser spot the centre fit models (LMS100: 0.015): a "
                                  "beam's echo is the spot-weighted mean range over the cylinder's face"},
                                 spot.divergence_rad, 0.0, 0.2);
  spot.exit_diameter_m = c.number({"/default/fit/spot/exit_diameter_m", "m",
                                   "spot diameter at the optics cover; the spot is this + range * "
                                   "divergence_rad wide"},
                                  spot.exit_diameter_m, 0.0, 0.1);
  spot.enabled = c.boolean({"/default/fit/spot/enabled", "",
                            "model the beam spot in the centre fit; false fits each beam's central ray "
                            "(reflector centres up to ~10 mm too far beyond 8 m with an LMS100)"},
                           spot.enabled);
  spot.background = c.boolean({"/default/fit/spot/background", "",
                               "model the surface a reflector stands in front of (a wall within "
                               "background_merge_distance_m behind it, read from the dull beams beside the "
                               "cluster): the part of a beam's spot that misses the cylinder lands there and "
                               "blends into its echo, reading it long; off: less variance for single-scan "
                               "fixes (refloc-survey drive turns it on for maps)"},
                              spot.background);
  spot.background_merge_distance_m = c.number(
      {"/default/fit/spot/background_merge_distance_m", "m",
       "returns along one beam closer than this blend into one echo (about the pulse's length): a surface "
       "farther behind the reflector's edge is not its background"},
      spot.background_merge_distance_m, 0.0, 5.0);
  e.fit.second_order_bias_correction = c.boolean(
      {"/default/fit/second_order_bias_correction", "",
       "remove the centre fit's second-order bias along the line of sight (half the model's curvature times "
       "the centre's covariance; 1-3 mm too close at 3-6 m without it); off: less variance for single-scan "
       "fixes (refloc-survey drive turns it on for maps)"},
      e.fit.second_order_bias_correction);
  KnownRadiusRoundnessConfig& r = e.roundness;
  r.lateral_margin = c.number({"/default/roundness/lateral_margin_m", "m",
                               "a cluster wider across the line of sight than the diameter plus this is no "
                               "reflector (plates, wide tape)"},
                              r.lateral_margin, 0.0, 1.0);
  r.min_lateral_fraction = c.number({"/default/roundness/min_lateral_fraction", "",
                                     "a cluster narrower than this fraction of the diameter (plus one beam "
                                     "step) is a glint on metal or a narrow strip"},
                                    r.min_lateral_fraction, 0.0, 1.0);
  r.max_rms_residual_sigmas = c.number({"/default/roundness/max_rms_residual_sigmas", "sigma",
                                        "largest RMS range residual of the fit in units of range_sigma_m; "
                                        "raise if real reflectors are rejected as not round"},
                                       r.max_rms_residual_sigmas, 0.1, 100.0);
  r.flat_chi2_margin = c.number({"/default/roundness/flat_chi2_margin", "",
                                 "chi2 by which a straight line may explain the beams better than the "
                                 "circle; lower rejects more flat tape"},
                                r.flat_chi2_margin, 0.0, 1000.0);
  r.radius_tolerance =
      c.positive_number({"/default/roundness/radius_tolerance_m", "m",
                         "with enough beams a free-radius fit must agree with reflector_radius_m within "
                         "max(this, radius_sigmas * its sigma)"},
                        r.radius_tolerance, 1.0, "0 would fail every radius check: nothing detected");
  r.radius_sigmas = c.number({"/default/roundness/radius_sigmas", "sigma",
                              "that tolerance in standard deviations of the free fit's radius"},
                             r.radius_sigmas, 0.0, 100.0);
  r.min_beams_for_radius_check = static_cast<int>(
      c.integer({"/default/roundness/min_beams_for_radius_check", "count",
                 "clusters with fewer beams skip the free-radius check (too few beams to see curvature)"},
                r.min_beams_for_radius_check, 4, 1000));
  return out;
}

ExtractorServiceConfig load_extractor_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  ExtractorServiceConfig config = parse_extractor_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
