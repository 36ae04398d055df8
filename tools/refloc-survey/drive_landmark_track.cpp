#include "drive_landmark_track.hpp"

#include "common/angles.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace refloc {

void LandmarkTrack::add(const TrackSighting& sighting) {
  if (sightings_.empty()) origin_ = sighting.map_p;
  sightings_.push_back(sighting);
  const Eigen::Vector2d q = sighting.map_p - origin_;
  sum_q_ += q;
  sum_u_ += sighting.map_direction;
  sum_qq_ += q.squaredNorm();
  sum_qu_ += q.dot(sighting.map_direction);
  // The direction it is seen from (towards the laser) unwrapped about the first: a track seen
  // all around spans just under 2 pi.
  const double view = std::atan2(-sighting.map_direction.y(), -sighting.map_direction.x());
  if (sightings_.size() == 1) first_view_ = view;
  const double relative = wrap_angle(view - first_view_);
  view_min_ = std::min(view_min_, relative);
  view_max_ = std::max(view_max_, relative);
}

Eigen::Vector2d LandmarkTrack::mean(double range_bias) const {
  if (sightings_.empty()) return origin_;
  return origin_ + (sum_q_ - range_bias * sum_u_) / static_cast<double>(sightings_.size());
}

double LandmarkTrack::scatter(double range_bias) const {
  if (sightings_.size() < 2) return 0.0;
  const double n = static_cast<double>(sightings_.size());
  const Eigen::Vector2d mean_q = (sum_q_ - range_bias * sum_u_) / n;
  const double mean_squared = (sum_qq_ - 2.0 * range_bias * sum_qu_ + range_bias * range_bias * n) / n;
  return std::sqrt(std::max(0.0, mean_squared - mean_q.squaredNorm()));
}

double LandmarkTrack::seen_fraction() const {
  if (expected_ <= 0) return sightings_.empty() ? 0.0 : 1.0;
  return std::min(1.0, static_cast<double>(sightings_.size()) / static_cast<double>(expected_));
}

std::string LandmarkTrack::promotion_failure(const PromotionRule& rule, double range_bias) const {
  if (sightings() < rule.min_sightings)
    return fmt::format("seen {} times (< {})", sightings(), rule.min_sightings);
  if (view_span() < rule.min_view_span)
    return fmt::format("seen over {:.1f} deg of directions (< {:.1f})", view_span() * 180.0 / M_PI,
                       rule.min_view_span * 180.0 / M_PI);
  if (scatter(range_bias) > rule.max_scatter)
    return fmt::format("centre scatters {:.1f} mm RMS across views (> {:.1f})", scatter(range_bias) * 1e3,
                       rule.max_scatter * 1e3);
  if (seen_fraction() < rule.min_seen_fraction)
    return fmt::format("seen in {:.0f} % of the scans it was in view (< {:.0f} %)", seen_fraction() * 100.0,
                       rule.min_seen_fraction * 100.0);
  return "";
}

}  // namespace refloc
