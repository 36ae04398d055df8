#pragma once
// Test helper: detections a laser at map_T_laser would report for a map, with
// Gaussian range/bearing noise, the range/field-of-view limits, shadowing by
// nearer reflectors and, optionally, walls. Header-only; shared by the matcher and
// solver tests and benchmarks.

#include "common/reflector_detection.hpp"
#include "common/reflector_map.hpp"
#include "common/se2.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace refloc::testing {

struct SyntheticSensor {
  double min_range = 0.3;                       ///< [m]
  double max_range = 20.0;                      ///< [m]
  double field_of_view = 270.0 * M_PI / 180.0;  ///< [rad]
  double range_sigma = 0.01;                    ///< [m]
  double bearing_sigma = 0.1 * M_PI / 180.0;    ///< [rad]
  bool shadowing = true;
  /// Walls: a reflector whose nearest surface point is behind one (the line to it crosses a
  /// segment) is not detected. Tested segment by segment, independently of the matcher's grid.
  std::vector<MapOccluder> occluders;
};

/// True when the open line from p to q crosses one of the occluders' segments.
inline bool crosses_occluder(const std::vector<MapOccluder>& occluders, const Eigen::Vector2d& p,
                             const Eigen::Vector2d& q) {
  const auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() * v.y() - u.y() * v.x();
  };
  const auto crosses = [&](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return cross(b - a, p - a) * cross(b - a, q - a) < 0.0 && cross(q - p, a - p) * cross(q - p, b - p) < 0.0;
  };
  for (const MapOccluder& o : occluders) {
    const size_t n = o.map_points.size();
    for (size_t i = 0; i + 1 < n; ++i)
      if (crosses(o.map_points[i], o.map_points[i + 1])) return true;
    if (o.closed && n > 2 && crosses(o.map_points[n - 1], o.map_points[0])) return true;
  }
  return false;
}

struct SyntheticScan {
  std::vector<ReflectorDetection> detections;  ///< sorted by bearing, as a scan would list them
  std::vector<int> map_index;                  ///< truth: map reflector index of each detection
};

/// Covariance of a point measured as (range, bearing) with these sigmas, to first order [m^2].
inline Eigen::Matrix2d polar_covariance(double range, double bearing, double range_sigma,
                                        double bearing_sigma) {
  Eigen::Matrix2d g;
  g << std::cos(bearing), -range * std::sin(bearing), std::sin(bearing), range * std::cos(bearing);
  return g * Eigen::Vector2d(range_sigma * range_sigma, bearing_sigma * bearing_sigma).asDiagonal() *
         g.transpose();
}

/// The map reflectors visible from map_T_laser, noise-free ranges and bearings in the laser frame.
inline std::vector<int> visible_reflectors(const ReflectorMap& map, const Pose2& map_T_laser,
                                           const SyntheticSensor& sensor) {
  const Pose2 laser_T_map = map_T_laser.inverse();
  std::vector<int> visible;
  for (size_t i = 0; i < map.reflectors.size(); ++i) {
    const Eigen::Vector2d p = laser_T_map * map.reflectors[i].map_p_center;
    const double r = p.norm(), b = std::atan2(p.y(), p.x());
    if (r < sensor.min_range || r > sensor.max_range || std::abs(b) > 0.5 * sensor.field_of_view) continue;
    const Eigen::Vector2d map_p_near =
        map.reflectors[i].map_p_center -
        map.reflectors[i].radius * (map.reflectors[i].map_p_center - map_T_laser.translation()).normalized();
    if (crosses_occluder(sensor.occluders, map_T_laser.translation(), map_p_near)) continue;
    bool shadowed = false;
    for (size_t j = 0; j < map.reflectors.size() && sensor.shadowing && !shadowed; ++j) {
      if (j == i) continue;
      const Eigen::Vector2d q = laser_T_map * map.reflectors[j].map_p_center;
      const double rq = q.norm();
      if (rq >= r) continue;
      const double half = std::asin(std::min(1.0, map.reflectors[i].radius / r)) +
                          std::asin(std::min(1.0, map.reflectors[j].radius / rq));
      shadowed = std::abs(angle_diff(std::atan2(q.y(), q.x()), b)) < half;
    }
    if (!shadowed) visible.push_back(static_cast<int>(i));
  }
  return visible;
}

/// Noisy detections of the visible reflectors; covariance is the linearised polar noise.
inline SyntheticScan render_detections(const ReflectorMap& map, const Pose2& map_T_laser,
                                       const SyntheticSensor& sensor, std::mt19937& rng) {
  std::normal_distribution<double> gauss(0.0, 1.0);
  const Pose2 laser_T_map = map_T_laser.inverse();
  SyntheticScan scan;
  for (int i : visible_reflectors(map, map_T_laser, sensor)) {
    const Eigen::Vector2d p = laser_T_map * map.reflectors[static_cast<size_t>(i)].map_p_center;
    const double r = p.norm() + sensor.range_sigma * gauss(rng);
    const double b = std::atan2(p.y(), p.x()) + sensor.bearing_sigma * gauss(rng);
    ReflectorDetection d;
    d.laser_p_center = {r * std::cos(b), r * std::sin(b)};
    d.range = r;
    d.bearing = b;
    d.covariance = polar_covariance(r, b, sensor.range_sigma, sensor.bearing_sigma);
    scan.detections.push_back(d);
    scan.map_index.push_back(i);
  }
  std::vector<size_t> order(scan.detections.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(),
            [&](size_t a, size_t b) { return scan.detections[a].bearing < scan.detections[b].bearing; });
  SyntheticScan sorted;
  for (size_t k : order) {
    sorted.detections.push_back(scan.detections[k]);
    sorted.map_index.push_back(scan.map_index[k]);
  }
  return sorted;
}

/// n reflectors uniformly in [0, width] x [0, height] [m], at least min_separation [m] apart, ids 1..n.
inline ReflectorMap random_map(int n, double width, double height, double min_separation, std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(0.0, width), uy(0.0, height);
  ReflectorMap map;
  while (static_cast<int>(map.reflectors.size()) < n) {
    const Eigen::Vector2d p(ux(rng), uy(rng));
    bool far_enough = true;
    for (const auto& r : map.reflectors)
      far_enough = far_enough && (r.map_p_center - p).norm() >= min_separation;
    if (!far_enough) continue;
    MapReflector r;
    r.id = static_cast<int>(map.reflectors.size()) + 1;
    r.map_p_center = p;
    map.reflectors.push_back(r);
  }
  return map;
}

/// A map from (x, y) pairs [m], ids 1..n.
inline ReflectorMap map_from_points(const std::vector<Eigen::Vector2d>& points) {
  ReflectorMap map;
  for (const auto& p : points) {
    MapReflector r;
    r.id = static_cast<int>(map.reflectors.size()) + 1;
    r.map_p_center = p;
    map.reflectors.push_back(r);
  }
  return map;
}

/// n racks: closed axis-aligned boxes with sides of 0.5-4 m in [0, width] x [0, height] [m],
/// none within 0.3 m of a reflector.
inline std::vector<MapOccluder> random_racks(const ReflectorMap& map, int n, double width, double height,
                                             std::mt19937& rng) {
  std::uniform_real_distribution<double> ux(0.0, width), uy(0.0, height), size(0.5, 4.0);
  std::vector<MapOccluder> racks;
  while (static_cast<int>(racks.size()) < n) {
    const Eigen::Vector2d lo(ux(rng), uy(rng)), hi = lo + Eigen::Vector2d(size(rng), size(rng));
    bool clear = true;
    for (const auto& r : map.reflectors) {
      const Eigen::Vector2d p = r.map_p_center;
      clear = clear &&
              !(p.x() > lo.x() - 0.3 && p.x() < hi.x() + 0.3 && p.y() > lo.y() - 0.3 && p.y() < hi.y() + 0.3);
    }
    if (!clear) continue;
    MapOccluder o;
    o.map_points = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};
    o.closed = true;
    racks.push_back(o);
  }
  return racks;
}

/// True when p lies in one of random_racks' boxes.
inline bool inside_a_rack(const std::vector<MapOccluder>& racks, const Eigen::Vector2d& p) {
  for (const MapOccluder& o : racks) {
    const Eigen::Vector2d lo = o.map_points[0], hi = o.map_points[2];
    if (p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y()) return true;
  }
  return false;
}

}  // namespace refloc::testing
