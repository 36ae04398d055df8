#pragma once
// A detection paired with its map reflector, as the solvers consume it.

#include "common/reflector_detection.hpp"

#include <Eigen/Core>

#include <vector>

namespace refloc {

struct PointObservation {
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();            ///< reflector centre in the map [m]
  Eigen::Vector2d laser_p = Eigen::Vector2d::Zero();          ///< measured centre in the laser frame [m]
  Eigen::Matrix2d information = Eigen::Matrix2d::Identity();  ///< inverse covariance of laser_p [1/m^2]
  double range = 0.0;                                         ///< |laser_p| [m]
  double bearing = 0.0;                                       ///< atan2 of laser_p [rad]
};

/// Fills out (cleared first) from matches into detections; matches whose detection_index is out
/// of range are skipped. Covariances get min_sigma^2 [m^2] added on the diagonal.
void make_observations(const std::vector<ReflectorDetection>& detections,
                       const std::vector<ReflectorMatch>& matches, double min_sigma,
                       std::vector<PointObservation>& out);

}  // namespace refloc
