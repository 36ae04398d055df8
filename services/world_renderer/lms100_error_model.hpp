#pragma once
// What an LMS100 does to a perfect measurement: range noise and limits, the
// widening beam (mixed pixels), and the received signal strength (RSSI).
// Figures from docs/lms100-protocol.md §5.5 and §8; where SICK publishes
// nothing (the 16-bit RSSI scale) the model is a documented assumption.
//
// RSSI model, in 16-bit units (8-bit = 16-bit / 257):
//  - diffuse: the lidar equation for an extended Lambertian target gives an
//    energy E = remission * cos(incidence) / range^2; the sensor reports it on a
//    logarithmic scale ("logarithmic, arbitrary unit", SICK OI), anchored so that
//    the datasheet's detection limit (10 % remission at 18 m) gives
//    rssi_at_detection_limit, rising rssi_per_decade per factor 10 of E, capped
//    at diffuse_rssi_max. Defaults: white paper at 1 m ~ 25000, 50 % at 10 m ~ 9400.
//  - retro-reflector (cylinder): saturated, retro_rssi_near minus a mild
//    retro_rssi_drop_per_m * range, times cos(incidence)^retro_incidence_exponent
//    (the film dims only towards the cylinder's silhouette).
//  - reflective tape: as bright as a reflector up to tape_full_incidence, then
//    falling linearly to nothing at tape_cutoff_incidence.
//  - metal: a specular lobe exp(-(incidence / metal_lobe_width)^2) * metal_rssi_peak,
//    or its weak diffuse part, whichever is brighter.
//  - partial hits: RSSI = (profile-weighted mean full-coverage RSSI of the parts
//    of the spot that returned) * c^rssi_coverage_exponent, c = the covered share
//    of the spot. Default exponent 0.5: edge hits are clearly dimmer (c = 0.25 ->
//    half), yet a reflector stays bright when the spot outgrows it (beyond ~8 m
//    the spot is wider than 120 mm, c < 1 even at the centre), as the brief's
//    "falls off only mildly with range" and the sensor's log scale suggest.
//    Exponent 1 = RSSI strictly proportional to coverage; then the paper's
//    threshold (8-bit 180) loses reflectors beyond ~8 m (bright beams per reflector
//    at 2/5/10/15 m: 5.7/2.0/0.6/0.0 with 1, 6.0/2.3/1.1/0.55 with 0.5). No LMS1xx
//    reflector RSSI sample exists (§10): this is an assumption to check.
//
// Systematic range error, added to the noise-free echo range before the noise:
//   range_offset + range * range_scale_ppm * 1e-6 + walk(echo RSSI)   (+ retro_range_bias on
//   the retro sub-rays of an echo, blended with the rest of the spot as a mixed pixel).
// walk(rssi) is range_walk_weak at or below range_walk_rssi_weak, range_walk_bright at or
// above range_walk_rssi_bright, linear between (RSSI of the noise-free echo, 16-bit units,
// so an edge beam half on a reflector gets an intermediate walk, as a real sensor does).
// What real sensors do: SICK specifies the LMS100 at +-30 mm systematic error (typical,
// 1..20 m, all remissions), i.e. what the offset, the scale and the walk together may
// reach. Default walk levels: every diffuse echo (at most diffuse_rssi_max) is "weak",
// a full reflector or tape return "bright". A pulsed time-of-flight receiver that times a threshold crossing
// sees a strong pulse earlier than a weak one (range walk): bright targets read short unless the firmware
// corrects with the pulse energy, and saturated retro-reflector returns are the part such a correction fits
// worst. Clock error and temperature drift of the time base scale every range (a few 100 ppm give millimetres
// at 10 m); the warm-up drift of the optics and electronics shows as offset. No LMS1xx measurement of the
// split exists in the project (docs/lms100-protocol.md §10), so every term defaults to 0. To reproduce the
// datasheet's worst case choose e.g. range_offset +-0.03, or range_scale_ppm 1500
// (+30 mm at 20 m), or a walk of range_walk_bright -0.03 (walls exact, reflector centres 30 mm
// short, their dimmer edge beams in between).
//
// RSSI output scale: "16bit" reports the 16-bit value as modelled; "8bit_in_16bit" is a
// sensor whose 16-bit RSSI channel carries 8-bit values (16-bit / 257, 0..255; seen on a
// real unit, and it made the extractor detect nothing). It changes only what is reported,
// not what the sensor detects.

#include <string>

namespace refloc {
class JsonConfig;
}

namespace refloc::sim {

/// What the sensor puts in its 16-bit RSSI channel (see the header comment).
enum class RssiScale { k16Bit, k8BitIn16Bit };
const char* to_string(RssiScale scale);

struct Lms100ErrorModel {
  // Range.
  double range_sigma = 0.012;  ///< statistical error, 1 sigma Gaussian [m] (SICK: 12 mm typical)
  /// range_sigma multiplier at the detection limit [-] (SICK: 20 mm maximum / 12 mm typical);
  /// echoes within one decade of energy above the limit blend linearly down to 1.
  double weak_echo_sigma_factor = 20.0 / 12.0;
  double range_offset = 0.0;       ///< systematic error added to every range [m] (SICK: up to +-30 mm)
  double range_scale_ppm = 0.0;    ///< range-proportional error [1e-6 of the range] (1000 = 1 mm per m)
  double range_walk_weak = 0.0;    ///< range walk of echoes at or below range_walk_rssi_weak [m]
  double range_walk_bright = 0.0;  ///< ... at or above range_walk_rssi_bright [m]
  /// [16-bit units]; default: the brightest diffuse echo (diffuse_rssi_max), so walls share one walk
  double range_walk_rssi_weak = 30000.0;
  double range_walk_rssi_bright = 60000.0;  ///< [16-bit units], above range_walk_rssi_weak; reflectors
  double range_min = 0.05;                  ///< nearer echoes are reported as no echo (0) [m]
  double range_max = 20.0;                  ///< farther echoes are reported as no echo (0) [m]
  bool quantize_to_mm = true;               ///< the sensor sends whole millimetres

  // Beam: the spot is beam_exit_diameter + range * beam_divergence wide (SICK OI §3.6.2).
  double beam_divergence = 0.015;     ///< full angle of the 1/e^2 spot [rad]
  double beam_exit_diameter = 0.008;  ///< spot diameter at the optics cover [m]
  int beam_subrays = 11;              ///< rays sampling the spot across its width [-], 1..31
  /// Returns closer together than this blend into one echo whose range is the
  /// energy-weighted mean (the mixed pixel); farther apart they are separate
  /// echoes and the nearest detectable one is reported (DIST1 is the first echo).
  double echo_merge_distance = 0.4;  ///< [m], about half the pulse length

  // Diffuse surfaces (logarithmic scale, see above).
  double detection_limit_remission = 0.10;  ///< remission detectable at detection_limit_range [-]
  double detection_limit_range = 18.0;      ///< [m] (datasheet: 18 m at 10 %)
  double rssi_at_detection_limit = 1000.0;  ///< weaker echoes are not detected [16-bit units]
  double rssi_per_decade = 7000.0;          ///< RSSI rise per factor 10 of energy [16-bit units]
  double diffuse_rssi_max = 30000.0;        ///< [16-bit units]; below the reflector band
  double max_incidence = 1.518;             ///< no diffuse echo beyond this incidence [rad] (87 deg)

  // Cylindrical retro-reflectors.
  double retro_rssi_near = 65000.0;       ///< [16-bit units]
  double retro_rssi_drop_per_m = 100.0;   ///< [16-bit units / m]
  double retro_incidence_exponent = 0.3;  ///< cos(incidence)^this [-]
  /// Extra range on returns from retro-reflectors and tape: the saturated pulse's walk
  /// error on some sensors (unknown for the LMS100, hence 0) [m].
  double retro_range_bias = 0.0;

  // Flat reflective tape.
  double tape_rssi_near = 64000.0;      ///< [16-bit units]
  double tape_full_incidence = 0.70;    ///< full brightness up to here [rad] (40 deg)
  double tape_cutoff_incidence = 1.31;  ///< no retro return beyond [rad] (75 deg)

  // Polished metal.
  double metal_rssi_peak = 64000.0;  ///< at normal incidence [16-bit units]
  double metal_lobe_width = 0.09;    ///< 1/e half-width of the specular lobe [rad] (5 deg)

  /// RSSI of a partial hit = mean RSSI of the covered part * coverage^this [-]; 1 = proportional.
  double rssi_coverage_exponent = 0.5;

  // Reported values.
  RssiScale rssi_scale = RssiScale::k16Bit;  ///< what the 16-bit RSSI channel carries
  double rssi_sigma = 150.0;                 ///< Gaussian noise on RSSI [16-bit units]
  double dazzle_range = 0.0;  ///< retro echoes nearer than this report code 1 "dazzled" [m]; 0 = never

  /// Energy of a diffuse echo at the detection limit [1/m^2].
  double detection_limit_energy() const {
    return detection_limit_remission / (detection_limit_range * detection_limit_range);
  }
  /// Spot diameter at a range [m].
  double spot_diameter(double range) const { return beam_exit_diameter + range * beam_divergence; }
};

/// RSSI of a diffuse surface fully covering the spot [16-bit units]; 0 when not detectable.
double diffuse_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range);
/// RSSI of a retro-reflector cylinder fully covering the spot [16-bit units].
double retro_reflector_rssi(const Lms100ErrorModel& model, double cos_incidence, double range);
/// RSSI of reflective tape fully covering the spot [16-bit units].
double tape_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range);
/// RSSI of polished metal fully covering the spot [16-bit units].
double metal_rssi(const Lms100ErrorModel& model, double remission, double cos_incidence, double range);

/// Range noise, 1 sigma, of an echo with this RSSI [m].
double range_sigma_for(const Lms100ErrorModel& model, double rssi);

/// Systematic range error of an echo at this noise-free range [m] with this RSSI [16-bit
/// units]: offset + scale + walk (retro_range_bias is applied per sub-ray, not here) [m].
double systematic_range_error(const Lms100ErrorModel& model, double range, double rssi);
/// The range walk part of it [m].
double range_walk(const Lms100ErrorModel& model, double rssi);
/// The value the sensor reports in its 16-bit RSSI channel for a 16-bit RSSI (as modelled,
/// or / 257 for RssiScale::k8BitIn16Bit); 65535 (dazzled) stays the channel's maximum.
double reported_rssi16(const Lms100ErrorModel& model, double rssi16);

/// Read the model from an object at pointer; absent keys keep the defaults. Angles
/// are in degrees in the file (keys *_deg), lengths in metres, RSSI in 16-bit units.
Lms100ErrorModel parse_lms100_error_model(const JsonConfig& config, const std::string& pointer);

}  // namespace refloc::sim
