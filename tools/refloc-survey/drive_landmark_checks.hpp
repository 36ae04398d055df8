#pragma once
// The survey's checks of its landmarks after a batch adjustment, each of which can take a
// landmark out of the map (it stays in the report with the reason):
//  - residuals: a cylinder's detections agree with one centre; a distractor's do not;
//  - spacing: two landmarks closer than two radii are one reflector mapped twice: merged;
//  - visibility: seen in too few of the scans that should have seen it (drive_visibility).

#include "drive_bundle_adjustment.hpp"
#include "drive_visibility.hpp"

#include "common/reflector_map.hpp"

#include <string>
#include <vector>

namespace refloc {

struct LandmarkCheckConfig {
  /// A landmark whose whitened residual RMS exceeds this is not a cylinder [-].
  double max_normalised_rms = 3.0;
  /// Same for the share of its detections beyond the Huber threshold [-].
  double max_outlier_fraction = 0.2;
  /// Two landmarks closer than this are one reflector mapped twice: merged [m] (2 radii + 10 mm).
  double merge_distance = 0.13;
  /// Seen in fewer than this share of the scans in which it was in view: not a cylinder [-].
  double min_visible_fraction = 0.4;
  /// ... judged only with at least this many such scans [-].
  int min_expected_scans = 50;
  VisibilityConfig visibility;
};

/// Drops (residuals) and merges (spacing) landmarks of p from b; true when p changed, and
/// then p's start values are b's solution. reasons[j] says why landmark j went.
bool check_residuals_and_spacing(const BundleResult& b, const LandmarkCheckConfig& config, BundleProblem& p,
                                 std::vector<std::string>& reasons);

/// Counts every landmark's visibility at b's poses with the occluders, drops the ones seen too
/// rarely; true when p changed. counts: one per landmark.
bool check_visibility(const BundleResult& b, const std::vector<MapOccluder>& occluders,
                      const LandmarkCheckConfig& config, BundleProblem& p, std::vector<std::string>& reasons,
                      std::vector<VisibilityCount>& counts);

}  // namespace refloc
