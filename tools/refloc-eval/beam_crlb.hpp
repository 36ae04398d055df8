#pragma once
// Cramér-Rao bound of the robot pose from the raw LMS100 measurements: every
// beam whose spot lies mostly on a reflector measures a range to a circle of
// known centre and radius with Gaussian noise sigma. No unbiased estimator that
// uses those ranges can beat this covariance; the accuracy study reports
// RMSE / bound.
//
// What a beam measures is modelled two ways:
//  - an ideal point beam: the range where the beam's axis meets the circle;
//  - the LMS100's real spot (8 mm at the optics, widening by 15 mrad): the
//    energy-weighted mean range over the part of the spot that lands on the
//    cylinder, as the sensor (and the emulator's renderer) reports it.
// The point model credits a beam grazing the silhouette with an unbounded
// sensitivity to the reflector's lateral position (d range / d lateral = tan of
// the incidence angle); a real spot averages over the curved edge and caps it.
// The spot model is the bound of the sensor we simulate; the point model is
// kept beside it to show what the beam width costs.

#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>
#include <optional>
#include <vector>

namespace refloc {

struct ReflectorBeam {
  double beam_angle = 0.0;  ///< in the laser frame [rad]
  int reflector_index = 0;  ///< into ReflectorMap::reflectors
};

/// The beam as the bound models it. Defaults: the LMS100 (SICK operating instructions §3.6.2)
/// and the emulator's retro-reflector return, energy proportional to cos(incidence)^0.3.
struct BeamSpotModel {
  double exit_diameter = 0.008;           ///< spot diameter at the optics cover [m]
  double divergence = 0.015;              ///< full angle of the 1/e^2 spot [rad]
  double retro_incidence_exponent = 0.3;  ///< return energy ~ cos(incidence)^this [-]
  /// Rays sampling the spot across its width [-]; 1 = an ideal point beam on the axis.
  int samples = 201;

  /// An ideal point beam: the range where the axis meets the circle.
  static BeamSpotModel point_beam() {
    BeamSpotModel m;
    m.samples = 1;
    return m;
  }
};

/// Noise-free range a beam at beam_angle in map_T_laser reports on a circle [m]; NaN when no
/// part of the spot meets it.
double expected_reflector_range(const Pose2& map_T_laser, double beam_angle,
                                const Eigen::Vector2d& map_p_center, double radius,
                                const BeamSpotModel& spot);

/// Covariance bound of (x, y, theta) of map_T_robot [m^2, m rad, rad^2]; empty with fewer than
/// 3 informative beams or a singular geometry.
std::optional<Eigen::Matrix3d> beam_range_crlb(const ReflectorMap& map, const Pose2& map_T_robot,
                                               const Pose2& robot_T_laser,
                                               const std::vector<ReflectorBeam>& beams, double range_sigma,
                                               const BeamSpotModel& spot);

}  // namespace refloc
