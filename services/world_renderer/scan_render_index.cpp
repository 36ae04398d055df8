#include "world_renderer/scan_render_index.hpp"

#include "common/plane_geometry.hpp"

#include <algorithm>
#include <cmath>

namespace refloc::sim {
void BeamCandidateIndex::add_all(int32_t code) {
  spans_.push_back({code, 0, static_cast<int32_t>(num_beams_) - 1});
}

void BeamCandidateIndex::add_interval(int32_t code, double lo, double hi) {
  if (hi - lo >= 2.0 * M_PI) {
    add_all(code);
    return;
  }
  // The interval may wrap around +-pi relative to the scan's angles.
  for (const double shift : {-2.0 * M_PI, 0.0, 2.0 * M_PI}) {
    const double first = std::ceil((lo + shift - start_angle_) / angle_increment_);
    const double last = std::floor((hi + shift - start_angle_) / angle_increment_);
    const double clamped_first = std::max(first, 0.0);
    const double clamped_last = std::min(last, static_cast<double>(num_beams_) - 1.0);
    if (clamped_first > clamped_last) continue;
    spans_.push_back({code, static_cast<int32_t>(clamped_first), static_cast<int32_t>(clamped_last)});
  }
}

void BeamCandidateIndex::build(const World& world, const std::vector<Pose2>& beam_poses, double start_angle,
                               double angle_increment, const BeamProfile& profile, double max_range) {
  build_from(world, nullptr, beam_poses, start_angle, angle_increment, profile, max_range);
}

void BeamCandidateIndex::build(const World& world, const std::vector<int>& reflectors,
                               const std::vector<Pose2>& beam_poses, double start_angle,
                               double angle_increment, const BeamProfile& profile, double max_range) {
  build_from(world, &reflectors, beam_poses, start_angle, angle_increment, profile, max_range);
}

void BeamCandidateIndex::build_from(const World& world, const std::vector<int>* listed,
                                    const std::vector<Pose2>& beam_poses, double start_angle,
                                    double angle_increment, const BeamProfile& profile, double max_range) {
  num_beams_ = beam_poses.size();
  start_angle_ = start_angle;
  angle_increment_ = angle_increment;
  spans_.clear();
  offsets_.assign(num_beams_ + 1, 0);
  entries_.clear();
  if (num_beams_ == 0) return;

  const Pose2& reference = beam_poses[num_beams_ / 2];
  const Pose2 laser_T_map = reference.inverse();
  double moved = 0.0;
  double turned = 0.0;
  for (const Pose2& p : beam_poses) {
    moved = std::max(moved, (p.translation() - reference.translation()).norm());
    turned = std::max(turned, std::abs(angle_diff(p.theta, reference.theta)));
  }
  const double radius = moved + profile.half_exit_diameter + 1e-6;
  const double pad = turned + std::atan(profile.half_divergence_tan) + 1e-6;
  const bool usable = angle_increment > 0.0 && std::isfinite(radius) && std::isfinite(pad);

  const auto& reflectors = world.reflectors.reflectors;
  const size_t count = listed != nullptr ? listed->size() : reflectors.size();
  for (size_t k = 0; k < count; ++k) {
    const size_t i = listed != nullptr ? static_cast<size_t>((*listed)[k]) : k;
    const int32_t code = static_cast<int32_t>(i);
    const Eigen::Vector2d c = laser_T_map * reflectors[i].map_p_center;
    const double distance = c.norm();
    const double reach = reflectors[i].radius + radius;
    if (!usable || distance <= reach) {
      add_all(code);
    } else if (distance - reach <= max_range) {
      const double bearing = std::atan2(c.y(), c.x());
      const double half = std::asin(reach / distance) + pad;
      add_interval(code, bearing - half, bearing + half);
    }
  }
  for (size_t i = 0; i < world.segments.size(); ++i) {
    const int32_t code = -static_cast<int32_t>(i) - 1;
    const Eigen::Vector2d a = laser_T_map * world.segments[i].map_p_a;
    const Eigen::Vector2d b = laser_T_map * world.segments[i].map_p_b;
    const double nearest = point_segment_distance(Eigen::Vector2d::Zero(), a, b);
    if (!usable || nearest <= radius) {
      add_all(code);
    } else if (nearest - radius <= max_range) {
      const double bearing_a = std::atan2(a.y(), a.x());
      const double sweep = std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b));
      const double half = std::asin(radius / nearest) + pad;
      add_interval(code, std::min(bearing_a, bearing_a + sweep) - half,
                   std::max(bearing_a, bearing_a + sweep) + half);
    }
  }

  // Counting sort of the spans into per-beam lists, reflectors first as they are in World.
  for (const Span& s : spans_) {
    for (int32_t beam = s.first_beam; beam <= s.last_beam; ++beam) ++offsets_[beam + 1];
  }
  for (size_t i = 0; i < num_beams_; ++i) offsets_[i + 1] += offsets_[i];
  entries_.resize(offsets_[num_beams_]);
  // offsets_[beam] serves as the fill cursor, then is restored from the next beam's start.
  for (const Span& s : spans_) {
    for (int32_t beam = s.first_beam; beam <= s.last_beam; ++beam) entries_[offsets_[beam]++] = s.code;
  }
  for (size_t i = num_beams_; i > 0; --i) offsets_[i] = offsets_[i - 1];
  offsets_[0] = 0;
}

}  // namespace refloc::sim
