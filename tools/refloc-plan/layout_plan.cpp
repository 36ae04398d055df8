#include "layout_plan.hpp"

#include <algorithm>
#include <cmath>

namespace refloc {

const char* cell_class(const CellPlan& cell, int min_matches) {
  if (cell.visible_min < min_matches) return "blind";
  if (cell.headings_ambiguous > 0) return "ambiguous";
  if (cell.headings_lost > 0) return "lost";
  if (cell.visible_min == min_matches) return "fragile";
  return "ok";
}

bool is_bad_cell(const CellPlan& cell, const PlanConfig& config) {
  return cell.visible_min < config.matcher.min_matches || cell.headings_ambiguous > 0 ||
         cell.headings_lost > 0 || !cell.has_bound || cell.sigma_xy_max > config.crlb_limit;
}

LayoutPlan plan_layout(const ReflectorMap& map, const PlanGrid& grid, const PlanConfig& config,
                       const PlanProgress& progress) {
  LayoutPlan plan;
  plan.grid = grid;
  PosePredictor predictor(map, config);
  const int headings = std::max(1, config.headings);
  plan.cells.reserve(grid.map_p_cells.size());
  for (size_t c = 0; c < grid.map_p_cells.size(); ++c) {
    CellPlan cell;
    cell.map_p = grid.map_p_cells[c];
    cell.visible_min = 1 << 30;
    cell.has_bound = true;
    for (int h = 0; h < headings; ++h) {
      const double heading = 2.0 * M_PI * h / headings;
      const PosePrediction p = predictor.predict(Pose2{cell.map_p.x(), cell.map_p.y(), heading});
      cell.visible_min = std::min(cell.visible_min, p.visible);
      cell.visible_mean += static_cast<double>(p.visible) / headings;
      cell.has_bound = cell.has_bound && p.has_bound;
      if (p.has_bound) {
        cell.sigma_xy_max = std::max(cell.sigma_xy_max, p.sigma_xy);
        cell.sigma_theta_max = std::max(cell.sigma_theta_max, p.sigma_theta);
      }
      const bool no_fix =
          p.relocalization == Relocalization::kLost || p.relocalization == Relocalization::kNoPose;
      if (no_fix) ++cell.headings_lost;
      if (p.relocalization == Relocalization::kUnique) ++cell.headings_unique;
      cell.headings_bad += p.visible < config.matcher.min_matches || no_fix ||
                           p.relocalization == Relocalization::kAmbiguous ||
                           p.relocalization == Relocalization::kWrong || !p.has_bound ||
                           p.sigma_xy > config.crlb_limit;
      if (p.relocalization == Relocalization::kAmbiguous || p.relocalization == Relocalization::kWrong) {
        if (!cell.has_rival) {
          cell.has_rival = true;
          cell.map_T_robot_rival = p.map_T_robot_rival;
          cell.rival_heading = heading;
        }
        ++cell.headings_ambiguous;
      }
    }
    plan.cells.push_back(cell);
    if (progress) progress(c + 1, grid.map_p_cells.size());
  }
  plan.summary = summarize(plan.cells, grid.resolution, config);
  return plan;
}

PlanSummary summarize(const std::vector<CellPlan>& cells, double resolution, const PlanConfig& config) {
  PlanSummary s;
  s.cells = cells.size();
  s.area_m2 = static_cast<double>(cells.size()) * resolution * resolution;
  if (cells.empty()) return s;
  std::vector<double> sigmas;
  double poses = 0.0;
  const int m = config.matcher.min_matches;
  for (const CellPlan& c : cells) {
    s.blind += c.visible_min < m;
    s.fragile += c.visible_min == m;
    s.ambiguous += c.visible_min >= m && c.headings_ambiguous > 0;
    s.lost += c.visible_min >= m && c.headings_ambiguous == 0 && c.headings_lost > 0;
    s.above_limit += !c.has_bound || c.sigma_xy_max > config.crlb_limit;
    s.bad += is_bad_cell(c, config);
    s.bad_poses += c.headings_bad;
    poses += std::max(config.headings, 1);
    if (c.has_bound) sigmas.push_back(c.sigma_xy_max);
  }
  const double n = static_cast<double>(cells.size());
  for (double* f : {&s.blind, &s.fragile, &s.ambiguous, &s.lost, &s.above_limit, &s.bad}) *f /= n;
  s.bad_poses /= poses;
  if (!sigmas.empty()) {
    std::nth_element(sigmas.begin(), sigmas.begin() + static_cast<long>(sigmas.size() / 2), sigmas.end());
    s.median_sigma_xy = sigmas[sigmas.size() / 2];
  }
  return s;
}

}  // namespace refloc
