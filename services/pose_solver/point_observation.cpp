#include "pose_solver/point_observation.hpp"

#include <Eigen/LU>

#include <cmath>

namespace refloc {

void make_observations(const std::vector<ReflectorDetection>& detections,
                       const std::vector<ReflectorMatch>& matches, double min_sigma,
                       std::vector<PointObservation>& out) {
  out.clear();
  for (const ReflectorMatch& m : matches) {
    if (m.detection_index < 0 || m.detection_index >= static_cast<int>(detections.size())) continue;
    const ReflectorDetection& d = detections[static_cast<size_t>(m.detection_index)];
    PointObservation o;
    o.map_p = m.map_p_center;
    o.laser_p = d.laser_p_center;
    Eigen::Matrix2d cov = d.covariance;
    cov(0, 0) += min_sigma * min_sigma;
    cov(1, 1) += min_sigma * min_sigma;
    // A covariance that is not positive definite (a faulty upstream value) must not give
    // negative weights: fall back to the floor alone.
    if (!cov.allFinite() || cov(0, 0) <= 0.0 || cov.determinant() <= 0.0) {
      cov = Eigen::Matrix2d::Identity() * min_sigma * min_sigma;
    }
    o.information = cov.inverse();
    o.range = d.laser_p_center.norm();
    o.bearing = std::atan2(d.laser_p_center.y(), d.laser_p_center.x());
    out.push_back(o);
  }
}

}  // namespace refloc
