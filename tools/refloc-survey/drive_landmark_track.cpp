#include "drive_landmark_track.hpp"

#include "common/angles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

void LandmarkTrack::add(const TrackSighting& sighting, double view_angle) {
  if (sightings_.empty()) first_view_ = view_angle;
  sightings_.push_back(sighting);
  const Eigen::Vector2d old_mean = mean_;
  mean_ += (sighting.map_p - mean_) / static_cast<double>(sightings_.size());
  sum_squared_distance_ += (sighting.map_p - old_mean).dot(sighting.map_p - mean_);
  // Unwrapped about the first view: the span of a track seen all around stays below 2 pi.
  const double relative = wrap_angle(view_angle - first_view_);
  view_min_ = std::min(view_min_, relative);
  view_max_ = std::max(view_max_, relative);
}

double LandmarkTrack::scatter() const {
  if (sightings_.size() < 2) return 0.0;
  return std::sqrt(std::max(0.0, sum_squared_distance_) / static_cast<double>(sightings_.size()));
}

double LandmarkTrack::seen_fraction() const {
  if (expected_ <= 0) return sightings_.empty() ? 0.0 : 1.0;
  return std::min(1.0, static_cast<double>(sightings_.size()) / static_cast<double>(expected_));
}

std::string LandmarkTrack::promotion_failure(const PromotionRule& rule) const {
  if (sightings() < rule.min_sightings)
    return fmt::format("seen {} times (< {})", sightings(), rule.min_sightings);
  if (view_span() < rule.min_view_span)
    return fmt::format("seen over {:.1f} deg of directions (< {:.1f})", view_span() * 180.0 / M_PI,
                       rule.min_view_span * 180.0 / M_PI);
  if (scatter() > rule.max_scatter)
    return fmt::format("centre scatters {:.1f} mm RMS across views (> {:.1f})", scatter() * 1e3,
                       rule.max_scatter * 1e3);
  if (seen_fraction() < rule.min_seen_fraction)
    return fmt::format("seen in {:.0f} % of the scans it was in view (< {:.0f} %)", seen_fraction() * 100.0,
                       rule.min_seen_fraction * 100.0);
  return "";
}

}  // namespace refloc
