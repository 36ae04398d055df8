#pragma once
// One LMS100 beam cast into a World: the spot is sampled by sub-rays across its
// width, each finds its nearest surface, and the returns are combined into the
// echo the sensor would report (mixed pixels included), then noise is added.
//
// Mixed-pixel model: the spot has a Gaussian profile whose 1/e^2 diameter is
// beam_exit_diameter + range * beam_divergence. Sub-ray k leaves the optics at a
// lateral offset u_k * exit_diameter / 2 with direction u_k * divergence / 2,
// u_k evenly spaced in [-1, 1], weight exp(-2 u_k^2) (normalised). Each sub-ray's
// return carries weight * full-coverage RSSI of the surface it hits. Returns
// closer than echo_merge_distance form one echo: RSSI = their sum (so partial
// hits are dimmer in proportion to coverage; rssi_coverage_exponent < 1 softens
// that), range = their RSSI-weighted mean (a mixed pixel between fore- and
// background, pulled towards the brighter one).
// The sensor reports the nearest echo whose RSSI reaches rssi_at_detection_limit.

#include "common/se2.hpp"
#include "world_renderer/lms100_error_model.hpp"
#include "world_renderer/world.hpp"

#include <array>
#include <cstdint>
#include <random>

namespace refloc::sim {

/// What a beam (mostly) saw; ground truth for tests, never visible to the sensor.
enum class HitKind : uint8_t { kNone, kReflector, kDiffuse, kTape, kMetal };

struct BeamTruth {
  HitKind kind = HitKind::kNone;  ///< surface giving most of the reported echo's energy
  int id = -1;                    ///< reflector id (kReflector) or segment index (others)
  double coverage = 0.0;          ///< share of the spot's profile on that surface [0, 1]
  double range = 0.0;             ///< noise-free echo range [m]; 0 without an echo
};

struct BeamEcho {
  double range = 0.0;  ///< [m]; 0 = no echo, 0.001 = dazzled (the sensor's codes 0 and 1)
  double rssi = 0.0;   ///< [16-bit units]; 0 without an echo
  BeamTruth truth;
};

constexpr int kMaxBeamSubrays = 31;

/// A subset of a world's primitives for one beam: reflector index r (into
/// world.reflectors.reflectors) is coded r, segment index s is coded -(s + 1).
struct BeamCandidates {
  const int32_t* begin = nullptr;
  const int32_t* end = nullptr;
};

/// Sub-ray layout of the spot, computed once from the model.
struct BeamProfile {
  int count = 0;
  std::array<double, kMaxBeamSubrays> lateral_offset{};  ///< at the optics cover [m]
  std::array<double, kMaxBeamSubrays> cos_angle{};       ///< direction relative to the beam axis
  std::array<double, kMaxBeamSubrays> sin_angle{};
  std::array<double, kMaxBeamSubrays> weight{};  ///< sums to 1
  double half_divergence_tan = 0.0;              ///< tan of the half angle [-]
  double half_exit_diameter = 0.0;               ///< [m]
};

/// Sub-ray layout for the model's beam (clamps beam_subrays to 1..kMaxBeamSubrays).
BeamProfile make_beam_profile(const Lms100ErrorModel& model);

/// Noise-free echo of the beam leaving map_p_origin towards map_angle [rad]; tests only
/// the candidates when given (see scan_render_index.hpp), else the whole world.
BeamEcho trace_beam(const World& world, const BeamProfile& profile, const Lms100ErrorModel& model,
                    const Eigen::Vector2d& map_p_origin, double map_angle,
                    const BeamCandidates* candidates = nullptr);

/// The echo the sensor reports for beam laser_angle [rad] from map_T_laser: traced,
/// then systematic range error (offset, scale, walk), range noise, limits, quantisation and RSSI noise
/// applied.
BeamEcho render_beam(const World& world, const BeamProfile& profile, const Lms100ErrorModel& model,
                     const Pose2& map_T_laser, double laser_angle, std::mt19937_64& rng,
                     const BeamCandidates* candidates = nullptr);

}  // namespace refloc::sim
