#include "reflector_extractor/synthetic_scan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

struct Hit {
  double range = std::numeric_limits<double>::infinity();
  double cos_incidence = 1.0;
  double rssi_8bit = 0.0;
};

void intersect_cylinder(const SyntheticCylinder& c, const Eigen::Vector2d& u, Hit& hit) {
  const double b = u.dot(c.laser_p_center);
  const double disc = b * b - c.laser_p_center.squaredNorm() + c.radius * c.radius;
  if (disc < 0.0) return;
  const double t = b - std::sqrt(disc);
  if (t <= 0.0 || t >= hit.range) return;
  const Eigen::Vector2d normal = (t * u - c.laser_p_center) / c.radius;
  hit.range = t;
  hit.cos_incidence = std::max(-u.dot(normal), 0.0);
  hit.rssi_8bit = c.rssi_8bit;
}

void intersect_segment(const SyntheticSegment& s, const Eigen::Vector2d& u, Hit& hit) {
  const Eigen::Vector2d d = s.laser_p_b - s.laser_p_a;
  const double denom = u.x() * d.y() - u.y() * d.x();
  if (std::abs(denom) < 1e-12) return;
  // Solve t u = a + s d.
  const double t = (s.laser_p_a.x() * d.y() - s.laser_p_a.y() * d.x()) / denom;
  const double along = (s.laser_p_a.x() * u.y() - s.laser_p_a.y() * u.x()) / denom;
  if (t <= 0.0 || t >= hit.range || along < 0.0 || along > 1.0) return;
  const Eigen::Vector2d normal = Eigen::Vector2d(-d.y(), d.x()).normalized();
  hit.range = t;
  hit.cos_incidence = std::abs(u.dot(normal));
  hit.rssi_8bit = s.rssi_8bit;
}

}  // namespace

LaserScan render_synthetic_scan(const SyntheticScene& scene, const SyntheticScanConfig& config,
                                std::mt19937& rng) {
  LaserScan scan;
  scan.utime = config.utime;
  scan.receive_utime = config.utime + 20'000;
  scan.start_angle = config.start_angle;
  scan.angle_increment = config.angle_increment;
  scan.time_increment = config.time_increment;
  scan.scan_period = 0.02;
  scan.range_max = config.range_max;
  scan.rssi_bits = 16;
  const size_t n = static_cast<size_t>(config.num_beams);
  scan.ranges.assign(n, 0.0f);
  scan.rssi.assign(n, 0);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (size_t i = 0; i < n; ++i) {
    const double angle = scan.beam_angle(i) + config.angle_sigma * unit(rng);
    const Eigen::Vector2d u(std::cos(angle), std::sin(angle));
    Hit hit;
    for (const SyntheticCylinder& c : scene.cylinders) intersect_cylinder(c, u, hit);
    for (const SyntheticSegment& s : scene.segments) intersect_segment(s, u, hit);
    if (!(hit.range <= config.range_max)) continue;  // no echo
    const double range = hit.range + config.range_sigma * unit(rng);
    const double energy = hit.rssi_8bit * (config.grazing_rssi_fraction +
                                           (1.0 - config.grazing_rssi_fraction) * hit.cos_incidence) +
                          config.rssi_sigma_8bit * unit(rng);
    scan.ranges[i] = static_cast<float>(std::max(range, scan.range_min));
    scan.rssi[i] = static_cast<int32_t>(std::clamp(energy, 0.0, 255.0) * 257.0);
  }
  return scan;
}

}  // namespace refloc
