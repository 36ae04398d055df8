#include "bright_beams.hpp"

#include "reflector_extractor/beam_table.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

sim::World beam_world_of(const ReflectorMap& map) {
  sim::World world;
  world.reflectors = map;
  world.reflectors.occluders.clear();
  for (const MapOccluder& o : map.occluders) {
    sim::add_polyline(world, o.map_points, o.closed, sim::SurfaceKind::kDiffuse,
                      sim::WorldSegment{}.remission);
  }
  return world;
}

BrightBeamCounter::BrightBeamCounter(const ReflectorMap& map, const PlanConfig& config, bool brute_force)
    : map_(map),
      scan_(config.scan),
      sensor_(config.sensor),
      energy_threshold_8bit_(config.extractor.energy_threshold_8bit),
      reject_occluded_(config.extractor.reject_occluded),
      occlusion_margin_(config.extractor.occlusion_margin),
      world_(beam_world_of(map)),
      profile_(sim::make_beam_profile(config.sensor)),
      brute_force_(brute_force),
      reach_(config.sensor.range_max + config.sensor.echo_merge_distance + 0.1),
      grid_(world_.reflectors, 0.5 * reach_) {
  for (const MapReflector& r : world_.reflectors.reflectors)
    largest_radius_ = std::max(largest_radius_, r.radius);
}

void BrightBeamCounter::index_scan(const Pose2& map_T_laser) {
  if (indexed_ && map_T_laser.x == indexed_pose_.x && map_T_laser.y == indexed_pose_.y &&
      map_T_laser.theta == indexed_pose_.theta) {
    return;
  }
  // Every reflector the index could keep: centre within reach + radius + the spot's exit radius
  // (BeamCandidateIndex's own test), with a centimetre to spare.
  nearby_.clear();
  grid_.query(map_T_laser.translation(), reach_ + largest_radius_ + profile_.half_exit_diameter + 0.01,
              nearby_);
  std::sort(nearby_.begin(), nearby_.end());
  beam_poses_.assign(static_cast<size_t>(std::max(scan_.num_beams, 0)), map_T_laser);
  index_.build(world_, nearby_, beam_poses_, scan_.start_angle, scan_.angle_increment, profile_, reach_);
  indexed_ = true;
  indexed_pose_ = map_T_laser;
}

int BrightBeamCounter::count(const Pose2& map_T_laser, int map_index) {
  const MapReflector& r = map_.reflectors[static_cast<size_t>(map_index)];
  const Eigen::Vector2d laser_p = map_T_laser.inverse() * r.map_p_center;
  const double range = laser_p.norm();
  if (range <= r.radius) return 0;
  const double bearing = std::atan2(laser_p.y(), laser_p.x());
  // The spot is wider than the axis: one beam beyond the silhouette on each side may still be
  // mostly on the cylinder.
  const double half_width = std::asin(r.radius / range) + scan_.angle_increment;
  const int first = std::max(
      0, static_cast<int>(std::ceil((bearing - half_width - scan_.start_angle) / scan_.angle_increment)));
  const int last = std::min(
      scan_.num_beams - 1,
      static_cast<int>(std::floor((bearing + half_width - scan_.start_angle) / scan_.angle_increment)));
  if (!brute_force_) index_scan(map_T_laser);
  const auto trace = [&](int b) {
    const double angle = map_T_laser.theta + scan_.start_angle + b * scan_.angle_increment;
    const sim::BeamCandidates candidates =
        brute_force_ ? sim::BeamCandidates{} : index_.candidates(static_cast<size_t>(b));
    return sim::trace_beam(world_, profile_, sensor_, map_T_laser.translation(), angle,
                           brute_force_ ? nullptr : &candidates);
  };
  const auto is_bright = [&](const sim::BeamEcho& echo) {
    // The extractor's own reading of a 16-bit RSSI on its 8-bit scale.
    return echo.truth.kind == sim::HitKind::kReflector && echo.truth.id == r.id &&
           rssi_to_8bit(static_cast<int32_t>(std::lround(echo.rssi)), 16) >= energy_threshold_8bit_;
  };
  int bright = 0, first_bright = -1, last_bright = -1;
  double first_range = 0.0, last_range = 0.0;
  for (int b = first; b <= last; ++b) {
    const sim::BeamEcho echo = trace(b);
    if (!is_bright(echo)) continue;
    ++bright;
    if (first_bright < 0) {
      first_bright = b;
      first_range = echo.range;
    }
    last_bright = b;
    last_range = echo.range;
  }
  if (bright == 0 || !reject_occluded_) return bright;
  const auto hides = [&](int neighbour, double edge_range) {
    if (neighbour < 0 || neighbour >= scan_.num_beams) return false;
    const sim::BeamEcho echo = trace(neighbour);
    return echo.truth.kind != sim::HitKind::kNone && echo.range > 0.0 &&
           echo.range < edge_range - occlusion_margin_;
  };
  return hides(first_bright - 1, first_range) || hides(last_bright + 1, last_range) ? 0 : bright;
}

}  // namespace refloc
