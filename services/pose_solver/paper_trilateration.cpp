#include "pose_solver/paper_trilateration.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>

namespace refloc {

bool trilaterate_position(const std::vector<PointObservation>& observations, const std::vector<char>* use,
                          double min_conditioning, Eigen::Vector2d& map_p_laser) {
  // Accumulate the normal equations of the C(n,2) difference rows directly: no n^2 matrix.
  // Row (i, j): 2 (X_j - X_i) X0 + 2 (Y_j - Y_i) Y0 = R_i^2 - R_j^2 - |P_i|^2 + |P_j|^2.
  Eigen::Matrix2d ata = Eigen::Matrix2d::Zero();
  Eigen::Vector2d atb = Eigen::Vector2d::Zero();
  int n = 0;
  const size_t count = observations.size();
  for (size_t i = 0; i < count; ++i) {
    if (use && !(*use)[i]) continue;
    ++n;
    const PointObservation& a = observations[i];
    for (size_t j = i + 1; j < count; ++j) {
      if (use && !(*use)[j]) continue;
      const PointObservation& b = observations[j];
      const Eigen::Vector2d row = 2.0 * (b.map_p - a.map_p);
      const double rhs =
          a.range * a.range - b.range * b.range - a.map_p.squaredNorm() + b.map_p.squaredNorm();
      ata += row * row.transpose();
      atb += row * rhs;
    }
  }
  if (n < 3) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(ata);
  const Eigen::Vector2d ev = eig.eigenvalues();  // ascending
  if (!(ev(1) > 0.0) || ev(0) < min_conditioning * ev(1)) return false;
  map_p_laser = ata.inverse() * atb;
  return map_p_laser.allFinite();
}

double paper_mean_heading(const std::vector<PointObservation>& observations,
                          const Eigen::Vector2d& map_p_laser) {
  if (observations.empty()) return 0.0;
  double sum = 0.0;
  for (const PointObservation& o : observations) {
    const Eigen::Vector2d d = o.map_p - map_p_laser;
    sum += wrap_angle(std::atan2(d.y(), d.x()) - o.bearing);  // eq. 6, each term wrapped
  }
  return wrap_angle(sum / static_cast<double>(observations.size()));  // eq. 7
}

double circular_mean_heading(const std::vector<PointObservation>& observations, const std::vector<char>* use,
                             const Eigen::Vector2d& map_p_laser) {
  double s = 0.0, c = 0.0;
  for (size_t i = 0; i < observations.size(); ++i) {
    if (use && !(*use)[i]) continue;
    const Eigen::Vector2d d = observations[i].map_p - map_p_laser;
    const double alpha = std::atan2(d.y(), d.x()) - observations[i].bearing;
    s += std::sin(alpha);
    c += std::cos(alpha);
  }
  return std::atan2(s, c);
}

Eigen::Vector2d paper_robot_position(const Eigen::Vector2d& map_p_laser, double robot_heading,
                                     const Pose2& robot_T_laser) {
  const double oo = std::hypot(robot_T_laser.x, robot_T_laser.y);
  const double beta = -std::atan2(-robot_T_laser.y, -robot_T_laser.x);
  return {map_p_laser.x() + oo * std::cos(robot_heading - beta),
          map_p_laser.y() + oo * std::sin(robot_heading - beta)};
}

}  // namespace refloc
