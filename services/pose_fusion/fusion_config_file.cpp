#include "pose_fusion/fusion_config_file.hpp"

#include "common/json_config.hpp"

namespace refloc {

FusionServiceConfig parse_fusion_service_config(const JsonConfig& config) {
  FusionServiceConfig c;
  FusionConfig& f = c.fusion;
  f.history =
      config.number({"/fusion/history_s", "s",
                     "odometry kept to apply a late fix at its scan's time: fixes older, or further ahead of "
                     "ODOMETRY, are dropped; longer re-applies more steps (100 Hz) per fix"},
                    f.history, 0.05, 10.0);
  f.max_fix_lead =
      config.number({"/fusion/max_fix_lead_s", "s",
                     "a fix newer than the latest ODOMETRY by more waits for odometry to reach its "
                     "time; within it, it corrects the latest estimate (may be gated out moving)"},
                    f.max_fix_lead, 0.0, 1.0);
  f.max_deferred_fixes = static_cast<size_t>(config.integer(
      {"/fusion/max_deferred_fixes", "count",
       "fixes kept waiting for ODOMETRY to catch up; beyond it the oldest is dropped (100: 2 s of "
       "fixes at 50 Hz)"},
      static_cast<long long>(f.max_deferred_fixes), 1, 100000));
  f.gate_chi2 = config.number({"/fusion/gate_chi2", "",
                               "a fix farther than this squared Mahalanobis distance from the estimate is "
                               "rejected (16.27: chi2 3 dof, 99.9 %); lower rejects more good fixes"},
                              f.gate_chi2, 0.1, 1e6);
  f.degraded_after =
      config.number({"/fusion/degraded_after_s", "s",
                     "no accepted fix for this long: POSE is DEGRADED (the navigator stops unless "
                     "drive_on_degraded_pose)"},
                    f.degraded_after, 0.01, 60.0);
  f.lost_after = config.number({"/fusion/lost_after_s", "s",
                                "no accepted fix for this long (>= degraded_after_s): LOST; the next OK fix "
                                "re-initialises the filter without the gate"},
                               f.lost_after, f.degraded_after, 600.0);
  f.max_consecutive_rejections = static_cast<int>(
      config.integer({"/fusion/max_consecutive_rejections", "count",
                      "this many gated-out fixes in a row: LOST, re-initialised from the next OK fix; lower "
                      "recovers sooner from a wrong estimate, trusts wrong fixes sooner"},
                     f.max_consecutive_rejections, 1, 100000));
  f.start_agreeing_usable_fixes = static_cast<int>(config.integer(
      {"/fusion/start_agreeing_degraded_fixes", "count",
       "with no OK LASER_POSE to start (or restart) from, this many DEGRADED ones (3 reflectors) within "
       "start_window_s that agree through the odometry (gate_chi2) start the filter: a pose_fusion restarted "
       "where the laser sees 3 reflectors; 0: only an OK fix starts it"},
      f.start_agreeing_usable_fixes, 0, 1000));
  f.start_window =
      config.number({"/fusion/start_window_s", "s",
                     "how far back the agreeing DEGRADED fixes of start_agreeing_degraded_fixes reach"},
                    f.start_window, 0.1, 600.0);
  const std::string measurements = config.choice(
      {"/measurements", "",
       "what corrects odometry: \"detections\" (each matched reflector of REFLECTOR_MATCHES at its scan's "
       "time; LASER_POSE only starts the filter) or \"laser_pose\" (the solver's single-scan fixes)"},
      "detections", {"detections", "laser_pose"});
  c.measurements =
      measurements == "detections" ? FusionMeasurements::kDetections : FusionMeasurements::kLaserPose;
  FusionModel& m = f.model;
  m.estimate_range_bias =
      config.boolean({"/model/estimate_range_bias", "",
                      "estimate the laser's common range offset (detections only); false: held at 0"},
                     m.estimate_range_bias);
  m.range_bias_prior_sigma_m =
      config.number({"/model/range_bias_prior_sigma_m", "m",
                     "1 sigma of the range offset before any scan (LMS100: +-30 mm)"},
                    m.range_bias_prior_sigma_m, 0.0, 1.0);
  m.range_bias_drift_m_per_sqrt_s = config.number(
      {"/model/range_bias_drift_m_per_sqrt_s", "m/sqrt(s)", "random walk of the range offset (temperature)"},
      m.range_bias_drift_m_per_sqrt_s, 0.0, 0.1);
  m.estimate_odometry_error = config.boolean(
      {"/model/estimate_odometry_error", "",
       "learn odometry's calibration error (3x3, true increment = (I + E) measured) from the laser; false: "
       "the odometry noise of robot.json is taken whole as random"},
      m.estimate_odometry_error);
  m.odometry_error_prior_sigma =
      config.number({"/model/odometry_error_prior_sigma", "",
                     "1 sigma of each element of E before any measurement (0.02: 2 % of the motion)"},
                    m.odometry_error_prior_sigma, 0.0, 0.5);
  m.odometry_error_walk_per_sqrt_m =
      config.number({"/model/odometry_error_walk_per_sqrt_m", "1/sqrt(m)",
                     "random walk of each element of E per metre driven (a radian turned counts as a "
                     "metre): how fast a changing load or floor may change the calibration"},
                    m.odometry_error_walk_per_sqrt_m, 0.0, 0.1);
  c.odometry_random_noise_fraction =
      config.number({"/model/odometry_random_noise_fraction", "",
                     "while E is estimated: the share of robot.json's odometry variance that is random "
                     "(slip, bumps); larger follows the laser more, smaller smooths more"},
                    c.odometry_random_noise_fraction, 0.001, 1.0);
  m.map_sigma_m =
      config.number({"/model/map_sigma_m", "m",
                     "1 sigma of each map reflector's position per axis (a surveyed map: 1-2 mm)"},
                    m.map_sigma_m, 0.0, 1.0);
  m.detection_gate_chi2 =
      config.number({"/model/detection_gate_chi2", "",
                     "a detection farther than this squared Mahalanobis distance from its prediction is "
                     "dropped (13.82: chi2 2 dof, 99.9 %); a scan with more dropped than kept is refused"},
                    m.detection_gate_chi2, 0.1, 1e6);
  m.min_detections_for_fix = static_cast<int>(
      config.integer({"/model/min_detections_for_fix", "count",
                      "accepted detections that make a scan a fresh fix (for OK / DEGRADED / LOST); fewer "
                      "still correct the estimate"},
                     m.min_detections_for_fix, 1, 100));
  m.max_noise_inflation =
      config.number({"/model/max_noise_inflation", "",
                     "when the kept detections' squared Mahalanobis distances average above 2, their "
                     "covariance is inflated to match, up to this factor (1: never); keeps POSE's covariance "
                     "honest on a host or sensor worse than the model"},
                    m.max_noise_inflation, 1.0, 1000.0);
  m.estimate_scan_time_offset = config.boolean(
      {"/model/estimate_scan_time_offset", "",
       "estimate the scans' time offset (true measurement time - stamp); false: stamps taken as exact"},
      m.estimate_scan_time_offset);
  m.scan_time_offset_prior_sigma_s = config.number(
      {"/model/scan_time_offset_prior_sigma_s", "s",
       "the scans' time offset before it is estimated, 1 sigma (a link delay no clock fit sees)"},
      m.scan_time_offset_prior_sigma_s, 0.0, 0.02);
  m.scan_time_offset_drift_s_per_sqrt_s =
      config.number({"/model/scan_time_offset_drift_s_per_sqrt_s", "s/sqrt(s)", "random walk of that offset"},
                    m.scan_time_offset_drift_s_per_sqrt_s, 0.0, 0.01);
  OdometryContinuityConfig& o = c.continuity;
  o.max_gap = config.number({"/continuity/max_gap_s", "s",
                             "ODOMETRY messages further apart: a seam (motion unobserved, covariance grown, "
                             "DEGRADED until a fix); keep >= mecanum_odometry's max_gap_s"},
                            o.max_gap, 0.01, 60.0);
  o.max_speed =
      config.number({"/continuity/max_speed_m_s", "m/s",
                     "the robot's top speed: sigma per second of a seam; an odometry step longer than "
                     "2 x this x its gap + 5 cm is refused as a jump. Keep above the real one"},
                    o.max_speed, 0.01, 10.0);
  o.max_yaw_rate =
      config.number({"/continuity/max_yaw_rate_rad_s", "rad/s",
                     "the robot's top yaw rate: heading sigma per second of a seam; a turn larger than "
                     "2 x this x its gap + 0.05 rad is refused as a jump"},
                    o.max_yaw_rate, 0.01, 20.0);
  o.distance_slack =
      config.number({"/continuity/distance_slack_m", "m",
                     "ODOMETRY's travelled distance may go back this much (rounding) before it "
                     "counts as a restarted odometry (a seam)"},
                    o.distance_slack, 0.0, 1.0);
  c.odometry_timeout =
      config.number({"/odometry_timeout_s", "s",
                     "no ODOMETRY for this long: each new usable fix is published itself as a "
                     "DEGRADED POSE; keep well above the ODOMETRY period (10 ms)"},
                    c.odometry_timeout, 0.01, 10.0);
  c.odometry_channel =
      config.string({"/odometry_channel", "",
                     "LCM channel of the wheel odometry read (odometry_t); POSE is published per message"},
                    c.odometry_channel);
  c.fix_channel = config.string(
      {"/fix_channel", "", "LCM channel of the solver's laser fixes read (pose2d_t)"}, c.fix_channel);
  c.matches_channel =
      config.string({"/matches_channel", "",
                     "LCM channel of the matcher's matched detections read with measurements \"detections\" "
                     "(reflector_matches_t)"},
                    c.matches_channel);
  c.output_channel =
      config.string({"/output_channel", "",
                     "LCM channel the fused pose is published on (pose2d_t, one per ODOMETRY message)"},
                    c.output_channel);
  for (const char* key : {"/odometry_channel", "/fix_channel", "/matches_channel", "/output_channel"}) {
    if (config.string(key, "x").empty()) config.fail(key, "expected a channel name, got \"\"");
  }
  return c;
}

FusionServiceConfig load_fusion_service_config(const std::string& path) {
  if (path.empty()) return {};
  const JsonConfig file = JsonConfig::load_file(path);
  FusionServiceConfig config = parse_fusion_service_config(file);
  file.reject_unknown_keys();
  return config;
}

}  // namespace refloc
