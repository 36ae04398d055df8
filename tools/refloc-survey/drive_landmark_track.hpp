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
  /// The measured centre through the front end's pose, no range offset taken off [m].
  Eigen::Vector2d map_p = Eigen::Vector2d::Zero();
  /// Its beam's direction in the map frame: a range offset b moves it by b along this [-].
  Eigen::Vector2d map_direction = Eigen::Vector2d::UnitX();
};

/// When a candidate becomes a map entry (all must hold).
struct PromotionRule {
  int min_sightings = 10;  ///< detections of it [-]
  /// The directions it was seen from span at least this (from the candidate to the laser) [rad]:
  /// a metal glint is only seen within ~5 deg of the plate's normal.
  double min_view_span = 15.0 * M_PI / 180.0;
  /// RMS distance of the sightings from their mean at most this [m]: a cylinder's centre does
  /// not move with the viewpoint, tape's and metal's do.
  double max_scatter = 0.025;
  /// Seen in at least this fraction of the scans in which it was in view (field of view,
  /// within expected_range, walls not known yet) since first seen [-]: a weak first filter; the
  /// batch's visibility check behind the traced walls is the strict one (drive_landmark_checks).
  double min_seen_fraction = 0.1;
};

/// Position and scatter are those of the sightings with a range offset b taken off (the front
/// end's current estimate, which may change after the sightings were made): the sums kept are
/// exact for any b.
class LandmarkTrack {
 public:
  void add(const TrackSighting& sighting);
  /// The scan saw the track's place in view (field of view, range) whether or not it was detected.
  void count_expected() { ++expected_; }

  /// Mean of the sightings, each moved back by range_bias along its beam [m].
  Eigen::Vector2d mean(double range_bias = 0.0) const;
  /// RMS distance of those sightings from their mean [m].
  double scatter(double range_bias = 0.0) const;
  double view_span() const { return view_max_ - view_min_; }  ///< [rad]
  int sightings() const { return static_cast<int>(sightings_.size()); }
  int expected() const { return expected_; }
  double seen_fraction() const;
  int last_scan() const { return sightings_.empty() ? -1 : sightings_.back().scan; }
  const std::vector<TrackSighting>& all_sightings() const { return sightings_; }

  /// "" when rule holds, else why not (the first failing test, with its number).
  std::string promotion_failure(const PromotionRule& rule, double range_bias = 0.0) const;

 private:
  std::vector<TrackSighting> sightings_;
  // Sums over sightings of q = p - origin (origin: the first sighting, against cancellation)
  // and u (the beam direction): mean = origin + (sum_q - b sum_u) / n and
  // sum |q - b u|^2 = sum_qq - 2 b sum_qu + b^2 n.
  Eigen::Vector2d origin_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d sum_q_ = Eigen::Vector2d::Zero();
  Eigen::Vector2d sum_u_ = Eigen::Vector2d::Zero();
  double sum_qq_ = 0.0;
  double sum_qu_ = 0.0;
  double first_view_ = 0.0;
  double view_min_ = 0.0, view_max_ = 0.0;  ///< relative to first_view_ [rad]
  int expected_ = 0;
};

}  // namespace refloc
