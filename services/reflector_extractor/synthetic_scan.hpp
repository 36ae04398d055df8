#pragma once
// A deliberately tiny scan simulator (ray-circle / ray-segment intersection, Gaussian
// range noise, RSSI falling off with incidence) so the extractor's tests, benchmark and
// the roundness calibration tool have ground truth. The realistic renderer lives in
// services/world_renderer/; this one only has to be simple and exactly known.

#include "common/laser_scan.hpp"

#include <Eigen/Core>

#include <random>
#include <vector>

namespace refloc {

struct SyntheticCylinder {
  Eigen::Vector2d laser_p_center = Eigen::Vector2d::Zero();  ///< [m]
  double radius = 0.06;                                      ///< [m]
  double rssi_8bit = 240.0;  ///< echo energy at normal incidence [8-bit scale]
};

/// A flat surface: reflective tape, a metal plate, or a dull wall.
struct SyntheticSegment {
  Eigen::Vector2d laser_p_a = Eigen::Vector2d::Zero();  ///< [m]
  Eigen::Vector2d laser_p_b = Eigen::Vector2d::Zero();  ///< [m]
  double rssi_8bit = 60.0;                              ///< [8-bit scale]
};

struct SyntheticScene {
  std::vector<SyntheticCylinder> cylinders;
  std::vector<SyntheticSegment> segments;
};

struct SyntheticScanConfig {
  int num_beams = 541;
  double start_angle = -135.0 * 3.14159265358979323846 / 180.0;   ///< [rad]
  double angle_increment = 0.5 * 3.14159265358979323846 / 180.0;  ///< [rad]
  double time_increment = 1.0 / (50.0 * 720.0);                   ///< 50 Hz rotation, 720 steps a turn [s]
  double range_sigma = 0.012;                                     ///< [m]
  double angle_sigma = 0.0;                                       ///< beam direction jitter [rad]
  double rssi_sigma_8bit = 4.0;
  /// RSSI = rssi_8bit * (grazing_rssi_fraction + (1 - grazing_rssi_fraction) * cos(incidence)).
  double grazing_rssi_fraction = 0.6;
  double range_max = 20.0;  ///< farther hits are "no echo" [m]
  int64_t utime = 1'000'000;
};

/// Render one scan (16-bit RSSI, like the LMS100) of scene; noise from rng.
LaserScan render_synthetic_scan(const SyntheticScene& scene, const SyntheticScanConfig& config,
                                std::mt19937& rng);

}  // namespace refloc
