#include "beam_crlb.hpp"

#include <Eigen/LU>
#include <cmath>

namespace refloc {
namespace {

/// Range along a beam from the laser to a circle; NaN when the beam misses it.
double beam_range(const Pose2& map_T_laser, double beam_angle, const Eigen::Vector2d& center, double radius) {
  const double a = map_T_laser.theta + beam_angle;
  const Eigen::Vector2d d(std::cos(a), std::sin(a));
  const Eigen::Vector2d oc = center - map_T_laser.translation();
  const double along = d.dot(oc);
  const double miss2 = oc.squaredNorm() - along * along;
  const double disc = radius * radius - miss2;
  if (disc < 0.0 || along <= 0.0) return std::nan("");
  return along - std::sqrt(disc);
}

}  // namespace

std::optional<Eigen::Matrix3d> beam_range_crlb(const ReflectorMap& map, const Pose2& map_T_robot,
                                               const Pose2& robot_T_laser, const std::vector<ReflectorBeam>& beams,
                                               double range_sigma) {
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  int informative = 0;
  constexpr double h = 1e-6;  // central differences of a smooth function: ~1e-10 relative error
  for (const auto& b : beams) {
    const MapReflector& r = map.reflectors[static_cast<size_t>(b.reflector_index)];
    Eigen::Vector3d gradient;
    bool ok = true;
    for (int k = 0; k < 3 && ok; ++k) {
      Pose2 plus = map_T_robot, minus = map_T_robot;
      (k == 0 ? plus.x : k == 1 ? plus.y : plus.theta) += h;
      (k == 0 ? minus.x : k == 1 ? minus.y : minus.theta) -= h;
      const double rp = beam_range(plus * robot_T_laser, b.beam_angle, r.map_p_center, r.radius);
      const double rm = beam_range(minus * robot_T_laser, b.beam_angle, r.map_p_center, r.radius);
      ok = std::isfinite(rp) && std::isfinite(rm);
      gradient[k] = (rp - rm) / (2.0 * h);
    }
    if (!ok) continue;
    information += gradient * gradient.transpose() / (range_sigma * range_sigma);
    ++informative;
  }
  if (informative < 3) return std::nullopt;
  Eigen::FullPivLU<Eigen::Matrix3d> lu(information);
  if (!lu.isInvertible()) return std::nullopt;
  return lu.inverse();
}

}  // namespace refloc
