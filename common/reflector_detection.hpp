#pragma once
// A reflector seen in one scan and its association with the map: the plain
// data passed extractor → matcher → solver (and by tools that call them directly).

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace refloc {

struct ReflectorDetection {
  Eigen::Vector2d laser_p_center = Eigen::Vector2d::Zero();         ///< centre in the laser frame [m]
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Identity() * 1e-4;  ///< of laser_p_center [m^2]
  double range = 0.0;                                               ///< |laser_p_center| [m]
  double bearing = 0.0;                                             ///< atan2 of laser_p_center [rad]
  int64_t utime = 0;  ///< host time of the cluster's middle beam [us]
  int first_beam = 0;
  int num_beams = 0;
  double mean_rssi = 0.0;
  double roundness_m = 0.0;      ///< mean circle-fit residual d-bar [m]
  double fitted_radius_m = 0.0;  ///< [m]
};

struct ReflectorMatch {
  int detection_index = -1;  ///< into the scan's detections
  int map_id = -1;
  Eigen::Vector2d map_p_center = Eigen::Vector2d::Zero();  ///< [m]
  double map_radius = 0.06;                                ///< [m]
};

}  // namespace refloc
