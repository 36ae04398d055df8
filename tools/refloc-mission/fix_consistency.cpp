#include "fix_consistency.hpp"

#include <Eigen/Cholesky>

#include <cmath>

namespace refloc {

std::optional<double> position_nees(const Eigen::Vector2d& error, const Eigen::Matrix2d& covariance) {
  if (!error.allFinite() || !covariance.allFinite()) return std::nullopt;
  const Eigen::LLT<Eigen::Matrix2d> llt(0.5 * (covariance + covariance.transpose()));
  if (llt.info() != Eigen::Success) return std::nullopt;
  const double nees = error.dot(llt.solve(error));
  if (!std::isfinite(nees) || nees < 0.0) return std::nullopt;
  return nees;
}

std::optional<double> heading_nees(double error, double variance) {
  if (!std::isfinite(error) || !std::isfinite(variance) || variance <= 0.0) return std::nullopt;
  return error * error / variance;
}

void ConsistencyAccumulator::add(const Eigen::Vector3d& error, const Eigen::Matrix3d& covariance) {
  ++sum_.fixes;
  const auto position = position_nees(error.head<2>(), covariance.topLeftCorner<2, 2>());
  const auto heading = heading_nees(error.z(), covariance(2, 2));
  if (!position || !heading) ++sum_.unusable_covariances;
  if (position) {
    ++position_count_;
    sum_.position_nees_mean += *position;
    sum_.position_outside_99 += *position > kChiSquare2Dof99 ? 1.0 : 0.0;
  }
  if (heading) {
    ++heading_count_;
    sum_.heading_nees_mean += *heading;
    sum_.heading_outside_99 += *heading > kChiSquare1Dof99 ? 1.0 : 0.0;
  }
}

ConsistencySummary ConsistencyAccumulator::summary() const {
  ConsistencySummary s = sum_;
  if (position_count_ > 0) {
    s.position_nees_mean /= position_count_;
    s.position_outside_99 /= position_count_;
  }
  if (heading_count_ > 0) {
    s.heading_nees_mean /= heading_count_;
    s.heading_outside_99 /= heading_count_;
  }
  return s;
}

nlohmann::json consistency_json(const ConsistencySummary& s) {
  return {{"nees_fixes", s.fixes},
          {"unusable_covariances", s.unusable_covariances},
          {"position_nees_mean", s.position_nees_mean},
          {"position_outside_99_percent", s.position_outside_99},
          {"heading_nees_mean", s.heading_nees_mean},
          {"heading_outside_99_percent", s.heading_outside_99}};
}

}  // namespace refloc
