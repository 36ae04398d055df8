#include "layout_plan.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <memory>
#include <mutex>
#include <system_error>
#include <thread>

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

namespace {

/// One cell at every heading, folded into its worst heading.
CellPlan plan_cell(PosePredictor& predictor, const Eigen::Vector2d& map_p, const PlanConfig& config) {
  const int headings = std::max(1, config.headings);
  CellPlan cell;
  cell.map_p = map_p;
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
    cell.headings_bad +=
        p.visible < config.matcher.min_matches || no_fix || p.relocalization == Relocalization::kAmbiguous ||
        p.relocalization == Relocalization::kWrong || !p.has_bound || p.sigma_xy > config.crlb_limit;
    if (p.relocalization == Relocalization::kAmbiguous || p.relocalization == Relocalization::kWrong) {
      if (!cell.has_rival) {
        cell.has_rival = true;
        cell.map_T_robot_rival = p.map_T_robot_rival;
        cell.rival_heading = heading;
      }
      ++cell.headings_ambiguous;
    }
  }
  return cell;
}

}  // namespace

LayoutPlan plan_layout(const ReflectorMap& map, const PlanGrid& grid, const PlanConfig& config,
                       const PlanProgress& progress) {
  LayoutPlan plan;
  plan.grid = grid;
  const size_t cells = grid.map_p_cells.size();
  plan.cells.resize(cells);
  // Built once, only read by the workers; each worker predicts with its own predictor (the
  // matcher's relocalizer, the solver, the beam tracer and their working memory).
  const auto shared = std::make_shared<const PlanMapIndex>(map, config);
  std::atomic<size_t> next{0};
  std::mutex mutex;  // guards done, error and the progress callback
  size_t done = 0;
  std::exception_ptr error;
  const auto work = [&] {
    try {
      PosePredictor predictor(shared, config);
      for (size_t c = next++; c < cells; c = next++) {
        plan.cells[c] = plan_cell(predictor, grid.map_p_cells[c], config);
        const std::lock_guard<std::mutex> lock(mutex);
        ++done;
        if (progress) progress(done, cells);
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      next = cells;  // the others stop after their current cell
    }
  };
  const size_t threads =
      std::min(static_cast<size_t>(std::max(config.threads, 1)), std::max<size_t>(cells, 1));
  std::vector<std::thread> workers;
  for (size_t t = 1; t < threads; ++t) {
    try {
      workers.emplace_back(work);
    } catch (const std::system_error&) {
      break;  // no more threads: the ones running take the rest
    }
  }
  work();
  for (std::thread& w : workers) w.join();
  if (error) std::rethrow_exception(error);
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
