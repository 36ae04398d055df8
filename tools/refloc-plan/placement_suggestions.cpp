#include "placement_suggestions.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

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

bool better(const SuggestionScore& a, const SuggestionScore& b) {
  if (a.ambiguous_poses != b.ambiguous_poses) return a.ambiguous_poses < b.ambiguous_poses;
  return a.bad_poses < b.bad_poses;
}

namespace {

SuggestionScore score_layout(const ReflectorMap& map, const PlanGrid& grid, const PlanConfig& coarse) {
  const LayoutPlan plan = plan_layout(map, grid, coarse);
  SuggestionScore score;
  for (const CellPlan& c : plan.cells) {
    score.ambiguous_poses += c.headings_ambiguous;
    score.bad_poses += c.headings_bad;
  }
  score.poses = std::max(
      1.0, static_cast<double>(plan.cells.size() * static_cast<size_t>(std::max(coarse.headings, 1))));
  return score;
}

/// map with reflectors at the chosen candidates, ids from first_id on.
ReflectorMap with_candidates(const ReflectorMap& map, const std::vector<Eigen::Vector2d>& candidates,
                             const std::vector<size_t>& chosen, int first_id, double radius) {
  ReflectorMap out = map;
  for (size_t k = 0; k < chosen.size(); ++k) {
    MapReflector r;
    r.id = first_id + static_cast<int>(k);
    r.map_p_center = candidates[chosen[k]];
    r.radius = radius;
    out.reflectors.push_back(r);
  }
  return out;
}

}  // namespace

std::vector<Suggestion> suggest_reflectors(const ReflectorMap& map,
                                           const std::vector<sim::DrivableArea>& drivable,
                                           const PlanConfig& plan_config, const SuggestionConfig& config,
                                           const PlanProgress& progress) {
  PlanConfig coarse = plan_config;
  coarse.resolution = config.resolution;
  coarse.headings = config.headings;
  const PlanGrid grid = make_plan_grid(map, drivable, config.resolution);
  int first_id = 1;
  for (const MapReflector& r : map.reflectors) first_id = std::max(first_id, r.id + 1);
  const std::vector<Eigen::Vector2d> candidates = candidate_positions(map, grid, config);
  const double min_gap = 2.0 * config.radius + kMinReflectorGap_m;
  // A candidate may join the chosen ones except the one at index skip (the place being swapped).
  const auto free_of = [&](const std::vector<size_t>& chosen, size_t c, size_t skip) {
    for (size_t k = 0; k < chosen.size(); ++k) {
      if (k != skip && (candidates[chosen[k]] - candidates[c]).norm() < min_gap) return false;
    }
    return true;
  };
  const size_t count = static_cast<size_t>(std::max(config.count, 0));
  const size_t total = candidates.size() * count * static_cast<size_t>(1 + std::max(config.swap_rounds, 0));
  size_t done = 0;
  const auto tick = [&] {
    if (progress) progress(std::min(++done, total), total);
  };
  const auto score_of = [&](const std::vector<size_t>& chosen) {
    return score_layout(with_candidates(map, candidates, chosen, first_id, config.radius), grid, coarse);
  };
  std::vector<size_t> chosen;
  SuggestionScore current = score_of(chosen);
  for (size_t k = 0; k < count && current.bad_poses > 0; ++k) {
    std::optional<size_t> best;
    SuggestionScore best_score = current;
    chosen.push_back(0);
    for (size_t c = 0; c < candidates.size(); ++c, tick()) {
      if (!free_of(chosen, c, chosen.size() - 1)) continue;
      chosen.back() = c;
      const SuggestionScore trial = score_of(chosen);
      if (better(trial, best_score)) {
        best_score = trial;
        best = c;
      }
    }
    if (!best) {  // nothing helps any more
      chosen.pop_back();
      break;
    }
    chosen.back() = *best;
    current = best_score;
  }
  // Greedy keeps its first choices although later ones may make them redundant: swap each for
  // the candidate that now does most, while that improves the layout.
  for (int round = 0; round < config.swap_rounds && !chosen.empty(); ++round) {
    bool changed = false;
    for (size_t k = 0; k < chosen.size(); ++k) {
      std::vector<size_t> trial_set = chosen;
      for (size_t c = 0; c < candidates.size(); ++c, tick()) {
        if (c == chosen[k] || !free_of(chosen, c, k)) continue;
        trial_set[k] = c;
        const SuggestionScore trial = score_of(trial_set);
        if (better(trial, current)) {
          current = trial;
          chosen[k] = c;
          changed = true;
        }
      }
    }
    if (!changed) break;
  }
  std::vector<Suggestion> out;
  std::vector<size_t> added;
  SuggestionScore before = score_of(added);
  for (size_t c : chosen) {
    added.push_back(c);
    const SuggestionScore after = score_of(added);
    Suggestion s;
    s.reflector.id = first_id + static_cast<int>(out.size());
    s.reflector.map_p_center = candidates[c];
    s.reflector.radius = config.radius;
    s.bad_poses_before = before.bad_poses / before.poses;
    s.bad_poses_after = after.bad_poses / after.poses;
    s.ambiguous_poses_before = before.ambiguous_poses / before.poses;
    s.ambiguous_poses_after = after.ambiguous_poses / after.poses;
    out.push_back(s);
    before = after;
  }
  return out;
}

}  // namespace refloc
