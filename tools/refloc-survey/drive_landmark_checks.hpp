#pragma once
// The survey's checks of its landmarks after a batch adjustment, each of which can take a
// landmark out of the map (it stays in the report with the reason):
//  - residuals: a cylinder's detections agree with one centre; a distractor's do not;
//  - spacing: two landmarks closer than two radii are one reflector mapped twice: merged;
//  - surface: a cylinder standing before a wall or rack has its centre at least about a radius
//    in front of that surface; the circle fitted to tape or a metal glint on the surface puts
//    its "centre" on or behind it (the traced occluders are the surfaces);
//  - visibility: seen in too few of the scans that should have seen it (drive_visibility).

#include "drive_bundle_adjustment.hpp"
#include "drive_visibility.hpp"

#include "common/reflector_map.hpp"

#include <cmath>
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
  /// A traced surface this close to a landmark's centre is the one it stands before [m] ...
  double surface_search = 0.25;
  /// ... when at least this long [m] (the traces of small pillars come out slanted) ...
  double min_surface_length = 0.8;
  /// ... and facing the mean direction it was seen from within 90 deg minus this [rad].
  double min_surface_view_angle = 15.0 * M_PI / 180.0;
  /// Its centre must lie at least this far in front of that surface, on the side it was seen
  /// from [m]: half the 60 mm radius, room for the surface's own tracing error.
  double min_surface_clearance = 0.03;
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

/// Signed distance of every landmark's centre in front of the nearest surface within
/// surface_search, positive on the side its laser poses were [m]; NaN without a surface.
std::vector<double> surface_clearances(const BundleResult& b, const BundleProblem& p,
                                       const std::vector<MapOccluder>& surfaces,
                                       const LandmarkCheckConfig& config);

/// Every landmark's visibility at b's poses behind the occluders (one count per landmark).
std::vector<VisibilityCount> landmark_visibility(const BundleResult& b, const BundleProblem& p,
                                                 const std::vector<MapOccluder>& occluders,
                                                 const LandmarkCheckConfig& config);

/// Drops landmarks on a surface (clearance) or seen too rarely (visibility); true when p changed.
bool check_surface_and_visibility(const BundleResult& b, const std::vector<MapOccluder>& occluders,
                                  const LandmarkCheckConfig& config, BundleProblem& p,
                                  std::vector<std::string>& reasons);

}  // namespace refloc
