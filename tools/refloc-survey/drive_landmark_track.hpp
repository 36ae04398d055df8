#pragma once
// What the survey knows about one bright thing it saw, reflector or not: every sighting in
// the map frame and the statistics that tell a cylinder from a distractor. A cylinder's fitted
// centre stays put whichever side it is seen from; the "centre" of a tape strip or of a metal
// glint slides with the viewpoint (the circle fit lands on whichever part is lit), a metal
// glint is seen only from within a few degrees of its normal, and tape only from near.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace refloc {

/// One detection of a track: which scan, which detection of it, where it put the centre.
struct TrackSighting {
  int scan = -1;
  int detection = -1;
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();  ///< centre through the front end's pose [m]
};

/// When a candidate becomes a map entry (all must hold).
struct PromotionRule {
  int min_sightings = 20;  ///< detections of it [-]
  /// The directions it was seen from span at least this (from the candidate to the laser) [rad]:
  /// a metal glint is only seen within ~5 deg of the plate's normal.
  double min_view_span = 20.0 * M_PI / 180.0;
  /// RMS distance of the sightings from their mean at most this [m]: a cylinder's centre does
  /// not move with the viewpoint, tape's and metal's do.
  double max_scatter = 0.025;
  /// Seen in at least this fraction of the scans in which it was in view (field of view,
  /// within expected_range, walls not known yet) since first seen [-]: a weak first filter; the
  /// batch's visibility check behind the traced walls is the strict one (drive_landmark_checks).
  double min_seen_fraction = 0.1;
};

class LandmarkTrack {
 public:
  /// view_angle: direction from the sighting to the laser in the map frame [rad].
  void add(const TrackSighting& sighting, double view_angle);
  /// The scan saw the track's place in view (field of view, range) whether or not it was detected.
  void count_expected() { ++expected_; }

  const Eigen::Vector2d& mean() const { return mean_; }
  /// RMS distance of the sightings from their mean [m].
  double scatter() const;
  double view_span() const { return view_max_ - view_min_; }  ///< [rad]
  int sightings() const { return static_cast<int>(sightings_.size()); }
  int expected() const { return expected_; }
  double seen_fraction() const;
  int last_scan() const { return sightings_.empty() ? -1 : sightings_.back().scan; }
  const std::vector<TrackSighting>& all_sightings() const { return sightings_; }

  /// "" when rule holds, else why not (the first failing test, with its number).
  std::string promotion_failure(const PromotionRule& rule) const;

 private:
  std::vector<TrackSighting> sightings_;
  Eigen::Vector2d mean_ = Eigen::Vector2d::Zero();
  double sum_squared_distance_ = 0.0;  ///< Welford: sum of |p - mean|^2 [m^2]
  double first_view_ = 0.0;
  double view_min_ = 0.0, view_max_ = 0.0;  ///< relative to first_view_ [rad]
  int expected_ = 0;
};

}  // namespace refloc
