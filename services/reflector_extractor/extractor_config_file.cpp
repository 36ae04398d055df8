#include "reflector_extractor/extractor_config_file.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

#include <fmt/format.h>

#include <cmath>

namespace refloc {

ExtractorServiceConfig parse_extractor_service_config(const JsonConfig& c) {
  ExtractorServiceConfig out;
  const std::string mode = c.choice("/mode", "default", {"default", "paper"});
  ExtractorConfig& e = out.extractor;
  e = mode == "paper" ? ExtractorConfig::paper() : ExtractorConfig{};

  out.input_channel = c.string("/input_channel", out.input_channel);
  out.output_channel = c.string("/output_channel", out.output_channel);
  out.odometry_channel = c.string("/odometry_channel", out.odometry_channel);
  out.motion_compensation = c.boolean("/motion_compensation", out.motion_compensation);
  out.odometry_max_age = c.number("/odometry_max_age_s", out.odometry_max_age, 0.0, 10.0);
  out.laser_pose_channel = c.string("/laser_pose_channel", out.laser_pose_channel);
  FixVelocityConfig& f = out.fix_velocity;
  f.enabled = c.boolean("/fix_velocity/enabled", f.enabled);
  f.window_s = c.positive_number("/fix_velocity/window_s", f.window_s, 2.0, "0 would keep no fix to fit");
  f.max_age_s = c.number("/fix_velocity/max_age_s", f.max_age_s, 0.0, 10.0);
  f.min_fixes = static_cast<int>(c.integer("/fix_velocity/min_fixes", f.min_fixes, 2, 100));
  f.min_span_s = c.positive_number("/fix_velocity/min_span_s", f.min_span_s, 2.0,
                                   "0 would fit a velocity to fixes at one instant");
  f.max_rms_residual_m = c.positive_number("/fix_velocity/max_rms_residual_m", f.max_rms_residual_m, 1.0,
                                           "0 would refuse every fit of noisy fixes");
  if (f.min_span_s > f.window_s)
    c.fail("/fix_velocity/min_span_s",
           fmt::format("{} s is longer than /fix_velocity/window_s {} s: no window "
                       "could ever hold it",
                       f.min_span_s, f.window_s));

  const std::string scale = c.choice("/rssi_scale", "auto", {"auto", "native", "8bit_in_16bit"});
  out.rssi_scale.mode = scale == "auto"     ? RssiScaleConfig::Mode::kAuto
                        : scale == "native" ? RssiScaleConfig::Mode::kNative
                                            : RssiScaleConfig::Mode::k8bitIn16bit;
  out.no_reflector_timeout = c.positive_number("/no_reflector_timeout_s", out.no_reflector_timeout, 3600.0,
                                               "0 would degrade the state on every scan without a reflector");

  e.energy_threshold_8bit = c.number("/energy_threshold_8bit", e.energy_threshold_8bit, 0.0, 255.0);
  e.reflector_radius = c.number("/reflector_radius_m", e.reflector_radius, 0.005, 1.0);
  e.min_beams = static_cast<int>(c.integer("/min_beams", e.min_beams, 1, 1000));

  e.clustering.lambda =
      c.number("/clustering/lambda_deg", e.clustering.lambda / kDegToRad, 1.0, 89.0) * kDegToRad;
  e.clustering.range_sigma = c.positive_number("/clustering/range_sigma_m", e.clustering.range_sigma, 0.5,
                                               "0 would split every cluster: nothing detected");
  e.clustering.max_gap_beams =
      static_cast<int>(c.integer("/clustering/max_gap_beams", e.clustering.max_gap_beams, -1, 100));

  e.paper_drop_points = static_cast<int>(c.integer("/paper/drop_points", e.paper_drop_points, 0, 20));
  e.paper_roundness.offset = c.number("/paper/roundness_offset_m", e.paper_roundness.offset, -1.0, 1.0);
  e.paper_roundness.slope = c.number("/paper/roundness_slope", e.paper_roundness.slope, -1.0, 1.0);
  const std::string centre =
      c.choice("/paper/centre", to_string(e.paper_centre), {"known_radius", "kasa", "polar"});
  e.paper_centre = centre == "kasa"    ? PaperCentreReading::kAlgebraicFreeRadius
                   : centre == "polar" ? PaperCentreReading::kPolar
                                       : PaperCentreReading::kKnownRadius;

  e.angle_sigma = c.number("/default/angle_sigma_rad", e.angle_sigma, 0.0, 0.1);
  e.edge_rssi_ratio = c.number("/default/edge_rssi_ratio", e.edge_rssi_ratio, 0.0, 1.0);
  e.occlusion_margin = c.number("/default/occlusion_margin_m", e.occlusion_margin, 0.0, 10.0);
  e.reject_occluded = c.boolean("/default/reject_occluded", e.reject_occluded);
  e.reject_next_to_dazzled = c.boolean("/default/reject_next_to_dazzled", e.reject_next_to_dazzled);
  e.fit.max_iterations =
      static_cast<int>(c.integer("/default/fit/max_iterations", e.fit.max_iterations, 1, 100));
  e.fit.min_incidence_cos = c.number("/default/fit/min_incidence_cos", e.fit.min_incidence_cos, 0.01, 1.0);
  KnownRadiusRoundnessConfig& r = e.roundness;
  r.lateral_margin = c.number("/default/roundness/lateral_margin_m", r.lateral_margin, 0.0, 1.0);
  r.min_lateral_fraction =
      c.number("/default/roundness/min_lateral_fraction", r.min_lateral_fraction, 0.0, 1.0);
  r.max_rms_residual_sigmas =
      c.number("/default/roundness/max_rms_residual_sigmas", r.max_rms_residual_sigmas, 0.1, 100.0);
  r.flat_chi2_margin = c.number("/default/roundness/flat_chi2_margin", r.flat_chi2_margin, 0.0, 1000.0);
  r.radius_tolerance = c.positive_number("/default/roundness/radius_tolerance_m", r.radius_tolerance, 1.0,
                                         "0 would fail every radius check: nothing detected");
  r.radius_sigmas = c.number("/default/roundness/radius_sigmas", r.radius_sigmas, 0.0, 100.0);
  r.min_beams_for_radius_check = static_cast<int>(
      c.integer("/default/roundness/min_beams_for_radius_check", r.min_beams_for_radius_check, 4, 1000));
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
