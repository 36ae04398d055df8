#include "reflector_extractor/paper_centre.hpp"

#include "common/angles.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace refloc {

const char* to_string(PaperCentreReading reading) {
  switch (reading) {
    case PaperCentreReading::kAlgebraicFreeRadius:
      return "kasa";
    case PaperCentreReading::kKnownRadius:
      return "known_radius";
    case PaperCentreReading::kPolar:
      break;
  }
  return "polar";
}

bool paper_polar_centre(const std::vector<FitBeam>& beams, double radius, int drop_points, double range_sigma,
                        CircleFit& out) {
  const int n = static_cast<int>(beams.size());
  const int begin = std::max(drop_points, 0);
  const int end = n - begin;
  if (end - begin < 1) return false;
  // Angles relative to the first beam, so a cluster astride +-pi averages correctly.
  const double first_angle = std::atan2(beams.front().direction.y(), beams.front().direction.x());
  double angle_sum = 0.0;
  for (const FitBeam& b : beams) {
    angle_sum += wrap_angle(std::atan2(b.direction.y(), b.direction.x()) - first_angle);
  }
  const double c_theta = wrap_angle(first_angle + angle_sum / n);
  double range_sum = 0.0;
  for (int i = begin; i < end; ++i) range_sum += beams[static_cast<size_t>(i)].range;
  const int central = end - begin;
  const double c_r = range_sum / central + radius;
  const Eigen::Vector2d along(std::cos(c_theta), std::sin(c_theta));
  const Eigen::Vector2d across(-along.y(), along.x());
  double step = 0.0;
  if (n >= 2) {
    const Eigen::Vector2d& u0 = beams[0].direction;
    const Eigen::Vector2d& u1 = beams[1].direction;
    step = std::abs(std::atan2(u0.x() * u1.y() - u0.y() * u1.x(), u0.dot(u1)));
  }
  const double across_sigma = step * c_r / std::sqrt(12.0);
  out.center = c_r * along;
  out.radius = radius;
  out.radius_sigma = 0.0;
  out.iterations = 0;
  out.chi2 = 0.0;
  out.covariance = range_sigma * range_sigma / central * along * along.transpose() +
                   across_sigma * across_sigma * across * across.transpose();
  return out.center.allFinite() && out.covariance.determinant() > 0.0;
}

bool paper_known_radius_centre(const std::vector<FitBeam>& beams, double radius, CircleFit& out) {
  // An incidence floor of 1 and no spot model make range_residual the plain geometric
  // |p - c| - radius: the paper's reading.
  KnownRadiusFitConfig geometric;
  geometric.min_incidence_cos = 1.0;
  geometric.spot.enabled = false;
  return fit_circle_known_radius(beams, radius, geometric, out);
}

}  // namespace refloc
