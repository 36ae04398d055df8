#include "drive_landmark_checks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace refloc {
namespace {

/// Observations of landmark j go to target[j]; -1 drops them. p's start values become b's.
void retarget(const BundleResult& b, const std::vector<int>& target, BundleProblem& p) {
  std::vector<BundleObservation> kept;
  kept.reserve(p.observations.size());
  for (BundleObservation z : p.observations) {
    z.landmark = target[static_cast<size_t>(z.landmark)];
    if (z.landmark >= 0) kept.push_back(z);
  }
  p.observations = std::move(kept);
  p.map_T_robot = b.map_T_robot;
  for (size_t j = 0; j < b.landmarks.size(); ++j) p.map_p_landmark[j] = b.landmarks[j].map_p;
}

std::vector<int> identity(size_t n) {
  std::vector<int> target(n);
  for (size_t j = 0; j < n; ++j) target[j] = static_cast<int>(j);
  return target;
}

}  // namespace

bool check_residuals_and_spacing(const BundleResult& b, const LandmarkCheckConfig& config, BundleProblem& p,
                                 std::vector<std::string>& reasons) {
  std::vector<int> target = identity(b.landmarks.size());
  bool changed = false;
  for (size_t j = 0; j < b.landmarks.size(); ++j) {
    const BundleLandmark& l = b.landmarks[j];
    if (l.observations == 0) continue;
    const double outlier_fraction = static_cast<double>(l.outliers) / l.observations;
    if (l.normalised_rms > config.max_normalised_rms || outlier_fraction > config.max_outlier_fraction) {
      reasons[j] = fmt::format(
          "residuals after the batch: {:.2f} normalised RMS, {:.0f} % beyond the robust "
          "threshold (a centre that moves with the view)",
          l.normalised_rms, outlier_fraction * 100.0);
      target[j] = -1;
      changed = true;
    }
  }
  for (size_t i = 0; i < b.landmarks.size(); ++i) {
    for (size_t j = i + 1; j < b.landmarks.size(); ++j) {
      if (target[i] != static_cast<int>(i) || target[j] != static_cast<int>(j)) continue;
      if (b.landmarks[i].observations == 0 || b.landmarks[j].observations == 0) continue;
      if ((b.landmarks[i].map_p - b.landmarks[j].map_p).norm() >= config.merge_distance) continue;
      target[j] = static_cast<int>(i);  // one reflector mapped twice: its detections go to the first
      changed = true;
    }
  }
  if (changed) retarget(b, target, p);
  return changed;
}

namespace {

/// Distance from c to the segment a-b [m].
double segment_distance(const Eigen::Vector2d& c, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((c - a).dot(ab) / std::max(ab.squaredNorm(), 1e-12), 0.0, 1.0);
  return (a + t * ab - c).norm();
}

}  // namespace

std::vector<double> surface_clearances(const BundleResult& b, const BundleProblem& p,
                                       const std::vector<MapOccluder>& surfaces,
                                       const LandmarkCheckConfig& config) {
  // Where each landmark was seen from: the mean of the laser positions of its detections.
  std::vector<Eigen::Vector2d> viewer(b.landmarks.size(), Eigen::Vector2d::Zero());
  std::vector<int> count(b.landmarks.size(), 0);
  for (const BundleObservation& z : p.observations) {
    viewer[static_cast<size_t>(z.landmark)] +=
        (b.map_T_robot[static_cast<size_t>(z.pose)] * p.robot_T_laser).translation();
    ++count[static_cast<size_t>(z.landmark)];
  }
  std::vector<double> out(b.landmarks.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t j = 0; j < b.landmarks.size(); ++j) {
    if (count[j] == 0) continue;
    const Eigen::Vector2d c = b.landmarks[j].map_p, from = viewer[j] / count[j];
    double nearest = config.surface_search;
    const Eigen::Vector2d view = (from - c).normalized();
    for (const MapOccluder& o : surfaces) {
      for (size_t i = 0; i + 1 < o.map_points.size(); ++i) {
        const Eigen::Vector2d& a = o.map_points[i];
        const Eigen::Vector2d along = o.map_points[i + 1] - a;
        // A surface it stands before is long and faces where it was seen from; the short
        // streaks of mixed pixels around a reflector run along the view and do not count.
        if (along.norm() < config.min_surface_length) continue;
        if (std::abs(along.normalized().dot(view)) > std::cos(config.min_surface_view_angle)) continue;
        const double d = segment_distance(c, a, o.map_points[i + 1]);
        if (d >= nearest) continue;
        nearest = d;
        Eigen::Vector2d normal = (o.map_points[i + 1] - a).normalized();
        normal = {-normal.y(), normal.x()};
        if (normal.dot(from - a) < 0.0) normal = -normal;  // towards where it was seen from
        out[j] = normal.dot(c - a);
      }
    }
  }
  return out;
}

std::vector<VisibilityCount> landmark_visibility(const BundleResult& b, const BundleProblem& p,
                                                 const std::vector<MapOccluder>& occluders,
                                                 const LandmarkCheckConfig& config) {
  std::vector<std::vector<char>> seen(b.landmarks.size(), std::vector<char>(b.map_T_robot.size(), 0));
  for (const BundleObservation& z : p.observations)
    seen[static_cast<size_t>(z.landmark)][static_cast<size_t>(z.pose)] = 1;
  std::vector<Eigen::Vector2d> positions;
  for (const BundleLandmark& l : b.landmarks) positions.push_back(l.map_p);
  return count_visibility(b.map_T_robot, p.robot_T_laser, positions, seen, occluders, config.visibility);
}

bool check_surface_and_visibility(const BundleResult& b, const std::vector<MapOccluder>& occluders,
                                  const LandmarkCheckConfig& config, BundleProblem& p,
                                  std::vector<std::string>& reasons) {
  const std::vector<double> clearance = surface_clearances(b, p, occluders, config);
  const std::vector<VisibilityCount> counts = landmark_visibility(b, p, occluders, config);
  std::vector<int> target = identity(b.landmarks.size());
  bool changed = false;
  for (size_t j = 0; j < b.landmarks.size(); ++j) {
    if (b.landmarks[j].observations == 0) continue;
    const VisibilityCount& c = counts[j];
    if (clearance[j] < config.min_surface_clearance) {  // false for NaN: no surface near
      reasons[j] = fmt::format(
          "its centre lies {:.0f} mm in front of the traced surface beside it (< {:.0f}): "
          "something on the surface (tape, metal), not a cylinder before it",
          clearance[j] * 1e3, config.min_surface_clearance * 1e3);
    } else if (c.expected >= config.min_expected_scans && c.fraction() < config.min_visible_fraction) {
      reasons[j] = fmt::format(
          "seen in {} of the {} scans it was in view within {:.1f} m ({:.0f} % < {:.0f} %)", c.seen,
          c.expected, config.visibility.max_range, c.fraction() * 100.0, config.min_visible_fraction * 100.0);
    } else {
      continue;
    }
    target[j] = -1;
    changed = true;
  }
  if (changed) retarget(b, target, p);
  return changed;
}

}  // namespace refloc
