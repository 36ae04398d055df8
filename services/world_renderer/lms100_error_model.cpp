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
  m.range_sigma = config.number({p + "/range_sigma", "m",
                                 "range noise, 1 sigma, of a clear echo (SICK: 12 mm typical); weak echoes "
                                 "get more (weak_echo_sigma_factor)"},
                                m.range_sigma, 0.0, 1.0);
  m.weak_echo_sigma_factor = config.number({p + "/weak_echo_sigma_factor", "",
                                            "range_sigma multiplier at the detection limit (SICK: 20 / 12 "
                                            "mm), falling to 1 one decade of energy above it"},
                                           m.weak_echo_sigma_factor, 1.0, 10.0);
  m.range_offset = config.number({p + "/range_offset", "m",
                                  "systematic error added to every range (SICK: up to +-30 mm); "
                                  "run_mission.sh --range-offset-mm sets it"},
                                 m.range_offset, -1.0, 1.0);
  m.range_scale_ppm = config.number(
      {p + "/range_scale_ppm", "ppm",
       "systematic error proportional to range (1000 = 1 mm per m), as a drifting time base gives"},
      m.range_scale_ppm, -20000.0, 20000.0);
  m.range_walk_weak = config.number(
      {p + "/range_walk_weak", "m",
       "systematic range error of weak echoes (RSSI <= range_walk_rssi_weak: walls, floor clutter)"},
      m.range_walk_weak, -0.5, 0.5);
  m.range_walk_bright = config.number({p + "/range_walk_bright", "m",
                                       "systematic range error of bright echoes (RSSI >= "
                                       "range_walk_rssi_bright: reflectors); -0.03 reads them 30 mm short"},
                                      m.range_walk_bright, -0.5, 0.5);
  m.range_walk_rssi_weak = config.number(
      {p + "/range_walk_rssi_weak", "16-bit RSSI",
       "echo RSSI at or below which the walk is range_walk_weak; default: the brightest diffuse echo"},
      m.range_walk_rssi_weak, 0.0, 65534.0);
  m.range_walk_rssi_bright = config.number(
      {p + "/range_walk_rssi_bright", "16-bit RSSI",
       "echo RSSI at or above which the walk is range_walk_bright; linear in between (edge beams)"},
      m.range_walk_rssi_bright, m.range_walk_rssi_weak + 1.0, 65535.0);
  m.range_min = config.number({p + "/range_min", "m", "echoes nearer than this are reported as no echo (0)"},
                              m.range_min, 0.0, 10.0);
  m.range_max = config.number(
      {p + "/range_max", "m", "echoes farther than this are reported as no echo (0); LMS100: 20 m"},
      m.range_max, m.range_min + 0.01, 100.0);
  m.quantize_to_mm = config.boolean(
      {p + "/quantize_to_mm", "", "round ranges to whole millimetres, as the sensor sends them"},
      m.quantize_to_mm);
  m.beam_divergence = config.number({p + "/beam_divergence", "rad",
                                     "full angle of the laser spot (1/e^2; LMS100: 15 mrad); wider spots "
                                     "give more mixed pixels at reflector edges"},
                                    m.beam_divergence, 0.0, 0.2);
  m.beam_exit_diameter =
      config.number({p + "/beam_exit_diameter", "m",
                     "spot diameter at the optics cover; the spot is this + range * beam_divergence wide"},
                    m.beam_exit_diameter, 0.0, 0.1);
  m.beam_subrays = static_cast<int>(config.integer(
      {p + "/beam_subrays", "count",
       "rays sampling the spot across its width: more is a finer mixed-pixel model and slower rendering"},
      m.beam_subrays, 1, 31));
  m.echo_merge_distance = config.number({p + "/echo_merge_distance", "m",
                                         "returns in one spot closer than this blend into one echo (mixed "
                                         "pixel); farther apart the nearest counts"},
                                        m.echo_merge_distance, 0.0, 10.0);
  m.detection_limit_remission = config.number(
      {p + "/detection_limit_remission", "",
       "remission (white paper ~1) just detected at detection_limit_range (datasheet: 0.1 at 18 m)"},
      m.detection_limit_remission, 0.01, 10.0);
  m.detection_limit_range = config.number(
      {p + "/detection_limit_range", "m",
       "range at which detection_limit_remission is just detected; lower it for a weaker sensor"},
      m.detection_limit_range, 0.1, 100.0);
  m.rssi_at_detection_limit =
      config.number({p + "/rssi_at_detection_limit", "16-bit RSSI",
                     "RSSI of a diffuse echo at the detection limit; weaker echoes are not detected"},
                    m.rssi_at_detection_limit, 1.0, 65534.0);
  m.rssi_per_decade = config.number({p + "/rssi_per_decade", "16-bit RSSI",
                                     "RSSI rise per factor 10 of diffuse echo energy (logarithmic scale); 0: "
                                     "every diffuse echo at the limit RSSI"},
                                    m.rssi_per_decade, 0.0, 65534.0);
  m.diffuse_rssi_max = config.number(
      {p + "/diffuse_rssi_max", "16-bit RSSI",
       "cap on diffuse (wall) echo RSSI; keep it below the reflectors' so RSSI tells them apart"},
      m.diffuse_rssi_max, 1.0, 65534.0);
  m.max_incidence = config.number({p + "/max_incidence_deg", "deg",
                                   "diffuse surfaces hit more obliquely than this give no echo"},
                                  m.max_incidence / kDegToRad, 0.0, 90.0) *
                    kDegToRad;
  m.retro_rssi_near = config.number({p + "/retro_rssi_near", "16-bit RSSI",
                                     "RSSI of a retro-reflector filling the spot head-on at 0 m (saturated)"},
                                    m.retro_rssi_near, 0.0, 65534.0);
  m.retro_rssi_drop_per_m = config.number(
      {p + "/retro_rssi_drop_per_m", "16-bit RSSI per m",
       "retro-reflector RSSI lost per metre of range; raise it to test the RSSI threshold at long range"},
      m.retro_rssi_drop_per_m, 0.0, 65534.0);
  m.retro_incidence_exponent = config.number(
      {p + "/retro_incidence_exponent", "",
       "reflector RSSI scales with cos(incidence)^this; higher dims the cylinder's silhouette edges more"},
      m.retro_incidence_exponent, 0.0, 10.0);
  m.retro_range_bias = config.number({p + "/retro_range_bias", "m",
                                      "extra range on retro-reflector and tape returns (saturated-pulse "
                                      "walk); unknown for the LMS100, hence 0"},
                                     m.retro_range_bias, -0.5, 0.5);
  m.tape_rssi_near = config.number(
      {p + "/tape_rssi_near", "16-bit RSSI",
       "RSSI of reflective tape (a distractor) head-on at 0 m; near reflector level, as real tape is"},
      m.tape_rssi_near, 0.0, 65534.0);
  m.tape_full_incidence = config.number({p + "/tape_full_incidence_deg", "deg",
                                         "reflective tape stays as bright as head-on up to this incidence"},
                                        m.tape_full_incidence / kDegToRad, 0.0, 90.0) *
                          kDegToRad;
  m.tape_cutoff_incidence =
      config.number({p + "/tape_cutoff_incidence_deg", "deg",
                     "reflective tape's bright return fades linearly to nothing at this incidence"},
                    m.tape_cutoff_incidence / kDegToRad, m.tape_full_incidence / kDegToRad + 0.1, 90.0) *
      kDegToRad;
  m.metal_rssi_peak =
      config.number({p + "/metal_rssi_peak", "16-bit RSSI",
                     "RSSI of polished metal head-on: a specular glint that looks like a reflector"},
                    m.metal_rssi_peak, 0.0, 65534.0);
  m.metal_lobe_width =
      config.number({p + "/metal_lobe_width_deg", "deg",
                     "1/e half-width of metal's specular lobe; wider makes glints visible from more angles"},
                    m.metal_lobe_width / kDegToRad, 0.1, 90.0) *
      kDegToRad;
  m.rssi_coverage_exponent = config.number({p + "/rssi_coverage_exponent", "",
                                            "partial-hit RSSI = mean RSSI * covered share^this; 1: "
                                            "proportional (far reflectors dim), 0: no dimming"},
                                           m.rssi_coverage_exponent, 0.0, 2.0);
  m.rssi_scale = config.choice({p + "/rssi_scale", "",
                                "\"8bit_in_16bit\": the 16-bit RSSI channel carries 8-bit values, as a real "
                                "unit did (tests the extractor's fallback)"},
                               to_string(m.rssi_scale), {"16bit", "8bit_in_16bit"}) == "16bit"
                     ? RssiScale::k16Bit
                     : RssiScale::k8BitIn16Bit;
  m.rssi_sigma = config.number({p + "/rssi_sigma", "16-bit RSSI", "Gaussian noise on each reported RSSI"},
                               m.rssi_sigma, 0.0, 10000.0);
  m.dazzle_range = config.number(
      {p + "/dazzle_range", "m",
       "retro-reflectors nearer than this report the \"dazzled\" code instead of a range; 0 = never"},
      m.dazzle_range, 0.0, 10.0);
  return m;
}

}  // namespace refloc::sim
