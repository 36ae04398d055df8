#include "drive_landmark_checks.hpp"

#include <fmt/format.h>

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

bool check_visibility(const BundleResult& b, const std::vector<MapOccluder>& occluders,
                      const LandmarkCheckConfig& config, BundleProblem& p, std::vector<std::string>& reasons,
                      std::vector<VisibilityCount>& counts) {
  std::vector<std::vector<char>> seen(b.landmarks.size(), std::vector<char>(b.map_T_robot.size(), 0));
  for (const BundleObservation& z : p.observations)
    seen[static_cast<size_t>(z.landmark)][static_cast<size_t>(z.pose)] = 1;
  std::vector<Eigen::Vector2d> positions;
  for (const BundleLandmark& l : b.landmarks) positions.push_back(l.map_p);
  counts = count_visibility(b.map_T_robot, p.robot_T_laser, positions, seen, occluders, config.visibility);
  std::vector<int> target = identity(b.landmarks.size());
  bool changed = false;
  for (size_t j = 0; j < b.landmarks.size(); ++j) {
    const VisibilityCount& c = counts[j];
    if (b.landmarks[j].observations == 0 || c.expected < config.min_expected_scans) continue;
    if (c.fraction() >= config.min_visible_fraction) continue;
    reasons[j] = fmt::format(
        "seen in {} of the {} scans it was in view within {:.1f} m ({:.0f} % < {:.0f} %)", c.seen, c.expected,
        config.visibility.max_range, c.fraction() * 100.0, config.min_visible_fraction * 100.0);
    target[j] = -1;
    changed = true;
  }
  if (changed) retarget(b, target, p);
  return changed;
}

}  // namespace refloc
