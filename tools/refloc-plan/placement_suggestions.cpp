#include "placement_suggestions.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

std::vector<Eigen::Vector2d> candidate_positions(const ReflectorMap& map, const PlanGrid& grid,
                                                 const SuggestionConfig& config) {
  // The side the robot is on: inside the hall's outline, outside racks and pillars.
  std::vector<std::pair<const MapOccluder*, bool>> sides;
  for (const MapOccluder& o : map.occluders) {
    if (!o.closed || o.map_points.size() < 3) continue;
    size_t inside = 0;
    for (const auto& p : grid.map_p_cells) inside += inside_polygon(o.map_points, p);
    sides.push_back({&o, 2 * inside > grid.map_p_cells.size()});
  }
  const double offset = config.radius + kMinReflectorGap_m;
  const auto fits = [&](const Eigen::Vector2d& p) {
    for (const auto& [o, inside] : sides) {
      if (inside_polygon(o->map_points, p) != inside) return false;
    }
    for (const MapReflector& r : map.reflectors) {
      if ((r.map_p_center - p).norm() < r.radius + config.radius + kMinReflectorGap_m) return false;
    }
    return true;
  };
  std::vector<Eigen::Vector2d> out;
  const double spacing = std::max(config.spacing, 0.01);
  for (const MapOccluder& o : map.occluders) {
    const size_t n = o.map_points.size();
    const size_t segments = o.closed && n > 2 ? n : n - 1;
    for (size_t s = 0; s < segments && n >= 2; ++s) {
      const Eigen::Vector2d a = o.map_points[s], b = o.map_points[(s + 1) % n];
      const double length = (b - a).norm();
      if (length < 1e-9) continue;
      const Eigen::Vector2d along = (b - a) / length, normal(-along.y(), along.x());
      for (double t = 0.5 * spacing; t < length; t += spacing) {
        for (const double side : {1.0, -1.0}) {
          const Eigen::Vector2d p = a + t * along + side * offset * normal;
          if (fits(p)) out.push_back(p);
        }
      }
    }
  }
  return out;
}

ReflectorMap with_suggestions(ReflectorMap map, const std::vector<Suggestion>& suggestions) {
  for (const Suggestion& s : suggestions) map.reflectors.push_back(s.reflector);
  return map;
}

std::vector<Suggestion> suggest_reflectors(const ReflectorMap& map,
                                           const std::vector<sim::DrivableArea>& drivable,
                                           const PlanConfig& plan_config, const SuggestionConfig& config,
                                           const PlanProgress& progress) {
  PlanConfig coarse = plan_config;
  coarse.resolution = config.resolution;
  coarse.headings = config.headings;
  const PlanGrid grid = make_plan_grid(map, drivable, config.resolution);
  std::vector<Suggestion> chosen;
  ReflectorMap current = map;
  int next_id = 1;
  for (const MapReflector& r : map.reflectors) next_id = std::max(next_id, r.id + 1);
  double bad = plan_layout(current, grid, coarse).summary.bad_poses;
  const size_t per_round = candidate_positions(current, grid, config).size();
  const size_t total = per_round * static_cast<size_t>(std::max(config.count, 0));
  size_t done = 0;
  for (int k = 0; k < config.count && bad > 0.0; ++k) {
    const std::vector<Eigen::Vector2d> candidates = candidate_positions(current, grid, config);
    double best_bad = bad;
    int best = -1;
    for (size_t c = 0; c < candidates.size(); ++c) {
      ReflectorMap trial = current;
      MapReflector r;
      r.id = next_id;
      r.map_p_center = candidates[c];
      r.radius = config.radius;
      trial.reflectors.push_back(r);
      const double trial_bad = plan_layout(trial, grid, coarse).summary.bad_poses;
      if (trial_bad < best_bad) {
        best_bad = trial_bad;
        best = static_cast<int>(c);
      }
      if (progress) progress(std::min(++done, total), total);
    }
    if (best < 0) break;  // nothing helps any more
    Suggestion s;
    s.reflector.id = next_id++;
    s.reflector.map_p_center = candidates[static_cast<size_t>(best)];
    s.reflector.radius = config.radius;
    s.bad_poses_before = bad;
    s.bad_poses_after = best_bad;
    current.reflectors.push_back(s.reflector);
    chosen.push_back(s);
    bad = best_bad;
  }
  return chosen;
}

}  // namespace refloc
