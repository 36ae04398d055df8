#include "world_renderer/lms100_error_model.hpp"

#include "common/angles.hpp"
#include "common/json_config.hpp"

#include <algorithm>
#include <cmath>

namespace refloc::sim {
namespace {

double incidence_of(double cos_incidence) { return std::acos(std::clamp(cos_incidence, 0.0, 1.0)); }

}  // namespace

double diffuse_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range) {
  if (cos_incidence < std::cos(model.max_incidence) || range <= 0.0) return 0.0;
  const double energy = remission * cos_incidence / (range * range);
  const double decades = std::log10(energy / model.detection_limit_energy());
  if (decades < 0.0) return 0.0;
  return std::min(model.rssi_at_detection_limit + model.rssi_per_decade * decades, model.diffuse_rssi_max);
}

double retro_reflector_rssi(const Lms100ErrorModel& model, double cos_incidence, double range) {
  const double near = model.retro_rssi_near - model.retro_rssi_drop_per_m * range;
  return std::max(0.0, near) * std::pow(std::clamp(cos_incidence, 0.0, 1.0), model.retro_incidence_exponent);
}

double tape_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range) {
  const double incidence = incidence_of(cos_incidence);
  double factor = 1.0;
  if (incidence >= model.tape_cutoff_incidence) {
    factor = 0.0;
  } else if (incidence > model.tape_full_incidence) {
    factor =
        (model.tape_cutoff_incidence - incidence) / (model.tape_cutoff_incidence - model.tape_full_incidence);
  }
  const double retro = std::max(0.0, model.tape_rssi_near - model.retro_rssi_drop_per_m * range) * factor;
  return std::max(retro, diffuse_rssi(model, remission, cos_incidence, range));
}

double metal_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range) {
  const double x = incidence_of(cos_incidence) / model.metal_lobe_width;
  const double specular = model.metal_rssi_peak * std::exp(-x * x);
  return std::max(specular, diffuse_rssi(model, remission, cos_incidence, range));
}

const char* to_string(RssiScale scale) { return scale == RssiScale::k16Bit ? "16bit" : "8bit_in_16bit"; }

double range_walk(const Lms100ErrorModel& model, double rssi) {
  const double span = model.range_walk_rssi_bright - model.range_walk_rssi_weak;
  const double t = span > 0.0 ? std::clamp((rssi - model.range_walk_rssi_weak) / span, 0.0, 1.0) : 1.0;
  return model.range_walk_weak + (model.range_walk_bright - model.range_walk_weak) * t;
}

double systematic_range_error(const Lms100ErrorModel& model, double range, double rssi) {
  return model.range_offset + range * model.range_scale_ppm * 1e-6 + range_walk(model, rssi);
}

double reported_rssi16(const Lms100ErrorModel& model, double rssi16) {
  if (model.rssi_scale == RssiScale::k16Bit || rssi16 <= 0.0) return rssi16;
  // The 8-bit scale's dazzle code is 255, as in the sensor's 8-bit channel.
  if (rssi16 >= 65535.0) return 255.0;
  return std::clamp(std::round(rssi16 / 257.0), 1.0, 254.0);
}

double range_sigma_for(const Lms100ErrorModel& model, double rssi) {
  if (model.rssi_per_decade <= 0.0) return model.range_sigma;
  const double weakness =
      std::clamp(1.0 - (rssi - model.rssi_at_detection_limit) / model.rssi_per_decade, 0.0, 1.0);
  return model.range_sigma * (1.0 + (model.weak_echo_sigma_factor - 1.0) * weakness);
}

Lms100ErrorModel parse_lms100_error_model(const JsonConfig& config, const std::string& p) {
  Lms100ErrorModel m;
  m.range_sigma = config.number(p + "/range_sigma", m.range_sigma, 0.0, 1.0);
  m.weak_echo_sigma_factor =
      config.number(p + "/weak_echo_sigma_factor", m.weak_echo_sigma_factor, 1.0, 10.0);
  m.range_offset = config.number(p + "/range_offset", m.range_offset, -1.0, 1.0);
  m.range_scale_ppm = config.number(p + "/range_scale_ppm", m.range_scale_ppm, -20000.0, 20000.0);
  m.range_walk_weak = config.number(p + "/range_walk_weak", m.range_walk_weak, -0.5, 0.5);
  m.range_walk_bright = config.number(p + "/range_walk_bright", m.range_walk_bright, -0.5, 0.5);
  m.range_walk_rssi_weak = config.number(p + "/range_walk_rssi_weak", m.range_walk_rssi_weak, 0.0, 65534.0);
  m.range_walk_rssi_bright = config.number(p + "/range_walk_rssi_bright", m.range_walk_rssi_bright,
                                           m.range_walk_rssi_weak + 1.0, 65535.0);
  m.range_min = config.number(p + "/range_min", m.range_min, 0.0, 10.0);
  m.range_max = config.number(p + "/range_max", m.range_max, m.range_min + 0.01, 100.0);
  m.quantize_to_mm = config.boolean(p + "/quantize_to_mm", m.quantize_to_mm);
  m.beam_divergence = config.number(p + "/beam_divergence", m.beam_divergence, 0.0, 0.2);
  m.beam_exit_diameter = config.number(p + "/beam_exit_diameter", m.beam_exit_diameter, 0.0, 0.1);
  m.beam_subrays = static_cast<int>(config.integer(p + "/beam_subrays", m.beam_subrays, 1, 31));
  m.echo_merge_distance = config.number(p + "/echo_merge_distance", m.echo_merge_distance, 0.0, 10.0);
  m.detection_limit_remission =
      config.number(p + "/detection_limit_remission", m.detection_limit_remission, 0.01, 10.0);
  m.detection_limit_range = config.number(p + "/detection_limit_range", m.detection_limit_range, 0.1, 100.0);
  m.rssi_at_detection_limit =
      config.number(p + "/rssi_at_detection_limit", m.rssi_at_detection_limit, 1.0, 65534.0);
  m.rssi_per_decade = config.number(p + "/rssi_per_decade", m.rssi_per_decade, 0.0, 65534.0);
  m.diffuse_rssi_max = config.number(p + "/diffuse_rssi_max", m.diffuse_rssi_max, 1.0, 65534.0);
  m.max_incidence =
      config.number(p + "/max_incidence_deg", m.max_incidence / kDegToRad, 0.0, 90.0) * kDegToRad;
  m.retro_rssi_near = config.number(p + "/retro_rssi_near", m.retro_rssi_near, 0.0, 65534.0);
  m.retro_rssi_drop_per_m =
      config.number(p + "/retro_rssi_drop_per_m", m.retro_rssi_drop_per_m, 0.0, 65534.0);
  m.retro_incidence_exponent =
      config.number(p + "/retro_incidence_exponent", m.retro_incidence_exponent, 0.0, 10.0);
  m.retro_range_bias = config.number(p + "/retro_range_bias", m.retro_range_bias, -0.5, 0.5);
  m.tape_rssi_near = config.number(p + "/tape_rssi_near", m.tape_rssi_near, 0.0, 65534.0);
  m.tape_full_incidence =
      config.number(p + "/tape_full_incidence_deg", m.tape_full_incidence / kDegToRad, 0.0, 90.0) * kDegToRad;
  m.tape_cutoff_incidence =
      config.number(p + "/tape_cutoff_incidence_deg", m.tape_cutoff_incidence / kDegToRad,
                    m.tape_full_incidence / kDegToRad + 0.1, 90.0) *
      kDegToRad;
  m.metal_rssi_peak = config.number(p + "/metal_rssi_peak", m.metal_rssi_peak, 0.0, 65534.0);
  m.metal_lobe_width =
      config.number(p + "/metal_lobe_width_deg", m.metal_lobe_width / kDegToRad, 0.1, 90.0) * kDegToRad;
  m.rssi_coverage_exponent = config.number(p + "/rssi_coverage_exponent", m.rssi_coverage_exponent, 0.0, 2.0);
  m.rssi_scale =
      config.choice(p + "/rssi_scale", to_string(m.rssi_scale), {"16bit", "8bit_in_16bit"}) == "16bit"
          ? RssiScale::k16Bit
          : RssiScale::k8BitIn16Bit;
  m.rssi_sigma = config.number(p + "/rssi_sigma", m.rssi_sigma, 0.0, 10000.0);
  m.dazzle_range = config.number(p + "/dazzle_range", m.dazzle_range, 0.0, 10.0);
  return m;
}

}  // namespace refloc::sim
