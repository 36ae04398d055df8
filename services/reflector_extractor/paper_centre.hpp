#pragma once
// Paper mode's centre (C_r, C_theta) of one cluster. The paper records the centre in polar
// coordinates (§3.3) and designs the reflector's diameter (120 mm, §2) but does not say how
// the centre is obtained from the points; these are the readings measured for issue 12
// (numbers and the choice in the extractor README, "Modes").

#include "reflector_extractor/circle_fit.hpp"

#include <vector>

namespace refloc {

enum class PaperCentreReading {
  kAlgebraicFreeRadius,  ///< Kasa algebraic circle, radius fitted too (paper mode before issue 12)
  kKnownRadius,          ///< geometric least squares of the centre with the designed radius fixed
  kPolar,                ///< C_theta = mean beam angle; C_r = mean range of the central beams + R
};

/// "kasa" / "known_radius" / "polar".
const char* to_string(PaperCentreReading reading);

/// The polar reading of beams (in beam order): C_theta = the mean angle of all beams, C_r = the
/// mean range of the beams without the first and last drop_points (the edge beams §3.3 calls
/// unreliable) + radius [m]. covariance: range_sigma^2 / m along the line of sight (m central
/// beams), a beam step / sqrt(12) across it (where the cluster's edges fall on the beam grid).
/// False when no central beam is left.
bool paper_polar_centre(const std::vector<FitBeam>& beams, double radius, int drop_points, double range_sigma,
                        CircleFit& out);

/// Least squares of sum w (|p - c| - radius)^2 over the centre c (Gauss-Newton, started one
/// radius behind the points; w = the beams' weights), covariance (J^T W J)^-1.
bool paper_known_radius_centre(const std::vector<FitBeam>& beams, double radius, CircleFit& out);

}  // namespace refloc
